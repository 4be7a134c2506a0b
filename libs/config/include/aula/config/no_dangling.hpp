#pragma once
// AULA_NO_DANGLING before a function that returns a reference into a long-lived table or into an
// argument that is not a temporary (`requireExercise(name)`, `requireRobot(world, name)`): GCC 14's
// -Wdangling-reference assumes such a reference may point into any temporary argument (a name built
// in the call), and warns at every `const T& x = f(g(...));`. The attribute says it never does.
// GCC 12 has no such warning and no such attribute.
#if defined(__has_cpp_attribute)
#if __has_cpp_attribute(gnu::no_dangling)
#define AULA_NO_DANGLING [[gnu::no_dangling]]
#endif
#endif
#ifndef AULA_NO_DANGLING
#define AULA_NO_DANGLING
#endif
