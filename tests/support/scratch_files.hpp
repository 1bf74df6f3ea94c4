#pragma once
// Scratch folders and whole files for the test suites.
//
// Contract:
// - ScratchDir makes a fresh folder of its own (mkdtemp) under GoogleTest's temporary folder
//   (::testing::TempDir(), which honours TEST_TMPDIR), named `<tag>_XXXXXX`: parallel test
//   processes, and several folders in one test, never share one. The destructor removes it with
//   everything in it. When it cannot be made, the test fails naming the place and path() is
//   empty. A ScratchDir can be moved (the moved-from one owns nothing), not copied.
// - write_file creates the missing parent folders and writes `text` as bytes.
// - read_file returns the whole file as bytes, or "" when it cannot be read: a missing file
//   shows as an empty text in the check that reads it.

#include <filesystem>
#include <string>
#include <vector>

namespace test_support {

namespace fs = std::filesystem;

class ScratchDir {
 public:
  /// `tag` starts the folder's name, to tell whose folder a leftover is.
  explicit ScratchDir(const std::string& tag = "test");
  ~ScratchDir();
  ScratchDir(ScratchDir&& other) noexcept;
  ScratchDir& operator=(ScratchDir&& other) noexcept;
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const fs::path& path() const { return path_; }
  /// The path of `name` inside the folder.
  fs::path operator/(const std::string& name) const { return path_ / name; }
  /// Names of the entries in the folder, sorted (no "." or "..").
  std::vector<std::string> entries() const;

 private:
  void remove();
  fs::path path_;
};

void write_file(const fs::path& path, const std::string& text);
std::string read_file(const fs::path& path);

}  // namespace test_support
