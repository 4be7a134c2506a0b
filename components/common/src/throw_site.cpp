#include "aula/component/throw_site.hpp"

#include <typeinfo>

#include <dlfcn.h>
#include <execinfo.h>

namespace aula::component {
namespace {

thread_local ThrowStack last_throw;
thread_local bool keeping = false;  // inside a KeepThrowSites

}  // namespace

const ThrowStack& lastThrowOnThisThread() { return last_throw; }

KeepThrowSites::KeepThrowSites() : was_(keeping) { keeping = true; }

KeepThrowSites::~KeepThrowSites() { keeping = was_; }

}  // namespace aula::component

#ifndef AULA_NO_THROW_SITE
// The C++ runtime's own, found next in the lookup order (libstdc++, or a sanitizer's interceptor).
extern "C" [[noreturn]] void __cxa_throw(void* object, std::type_info* type, void (*destroy)(void*)) {
  using Throw = void (*)(void*, std::type_info*, void (*)(void*));
  static const auto runtime_throw = reinterpret_cast<Throw>(dlsym(RTLD_NEXT, "__cxa_throw"));
  aula::component::ThrowStack& stack = aula::component::last_throw;
  const bool keep = aula::component::keeping;
  stack.object = keep ? object : nullptr;
  stack.count = keep ? ::backtrace(stack.frames, sizeof stack.frames / sizeof stack.frames[0]) : 0;
  runtime_throw(object, type, destroy);
  __builtin_unreachable();
}
#endif
