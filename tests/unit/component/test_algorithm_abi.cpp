// The plugin ABI version is checked against the API's headers: their hash (taken by CMake,
// cmake/AulaApi.cmake) must be the one recorded next to the version in algorithm_plugin.hpp. An
// API change fails this test until the version is raised and the new hash recorded; comments and
// white space are not part of the hash.
#include <aula/component/algorithm_plugin.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace {

// The hash cmake/aula_api_hash.cmake gives for `headers` (DIR:FILE;... under `root`).
std::string hashOf(const std::string& root, const std::string& headers) {
  const std::string command = std::string(AULA_CMAKE_COMMAND) + " -DROOT=" + root + " \"-DHEADERS=" + headers +
                              "\" -P " + AULA_SOURCE_DIR + "/cmake/aula_api_hash.cmake 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> out(popen(command.c_str(), "r"), pclose);
  std::string text;
  std::array<char, 256> buffer{};
  while (out && fgets(buffer.data(), buffer.size(), out.get()) != nullptr) text += buffer.data();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST(AlgorithmAbi, TheVersionWasRaisedWhenTheApiHeadersChanged) {
  EXPECT_STREQ(AULA_API_HEADERS_SHA256, AULA_ALGORITHM_ABI_HEADERS_SHA256)
      << "The plugin API's headers (AULA_API_HEADERS, cmake/AulaApi.cmake) changed since ABI version "
      << AULA_ALGORITHM_ABI_VERSION << " was recorded: a plugin built before would be loaded with another layout. "
      << "In components/common/include/aula/component/algorithm_plugin.hpp raise AULA_ALGORITHM_ABI_VERSION to "
      << AULA_ALGORITHM_ABI_VERSION + 1 << " and set AULA_ALGORITHM_ABI_HEADERS_SHA256 to \"" << AULA_API_HEADERS_SHA256
      << "\".";
}

TEST(AlgorithmAbi, TheHashFollowsTheDeclarationsNotTheComments) {
  const std::string root = testing::TempDir() + "aula_abi_hash";
  std::filesystem::create_directories(root);
  write(root + "/api.hpp", "// A device.\nstruct Device {\n  double v_mps;\n};\n");
  const std::string before = hashOf(root, "x:api.hpp");
  ASSERT_EQ(before.size(), 64u) << before;
  write(root + "/api.hpp", "// A device, reworded.\nstruct Device {\n    double v_mps;  // metres per second\n};\n");
  EXPECT_EQ(hashOf(root, "x:api.hpp"), before) << "comments and indentation are not the ABI";
  write(root + "/api.hpp", "// A device.\nstruct Device {\n  double v_mps;\n  double w_radps;\n};\n");
  EXPECT_NE(hashOf(root, "x:api.hpp"), before) << "a new member is";
  write(root + "/algorithm_plugin.hpp", "#define AULA_ALGORITHM_ABI_HEADERS_SHA256 \"...\"\n");
  EXPECT_EQ(hashOf(root, "x:api.hpp;c:algorithm_plugin.hpp"), hashOf(root, "x:api.hpp"))
      << "the header that records the hash is not hashed";
}
