// --output=FILE appears complete or not at all (output_file.hpp).

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <vector>

#include "output_file.hpp"
#include "scratch_files.hpp"

namespace gen_hazards {
namespace {

using test_support::read_file;
using TempDir = test_support::ScratchDir;

TEST(GenHazardsOutputFile, WritesTheWholeTextAndNothingElse) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  const std::string path = (dir / "field.txt").string();
  const std::string text(200000, 'x');  // more than one write() may take
  EXPECT_EQ(write_file_atomically(path, text), std::nullopt);
  EXPECT_EQ(read_file(path), text);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"field.txt"});  // no temporary left
}

TEST(GenHazardsOutputFile, ReplacesAnExistingFile) {
  TempDir dir;
  const std::string path = (dir / "field.txt").string();
  std::ofstream(path) << "old content that is longer than the new one\n";
  EXPECT_EQ(write_file_atomically(path, "new\n"), std::nullopt);
  EXPECT_EQ(read_file(path), "new\n");
}

TEST(GenHazardsOutputFile, NewFileGetsTheUsualPermissions) {
  TempDir dir;
  const std::string path = (dir / "field.txt").string();
  const mode_t old_mask = ::umask(022);
  EXPECT_EQ(write_file_atomically(path, "x\n"), std::nullopt);
  ::umask(old_mask);
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

TEST(GenHazardsOutputFile, FailureNamesThePathAndLeavesNothing) {
  TempDir dir;
  const std::string path = (dir / "no_such_folder/field.txt").string();
  const auto error = write_file_atomically(path, "x\n");
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find(path), std::string::npos) << *error;
  EXPECT_TRUE(dir.entries().empty());

  // A folder in the way of the rename: the temporary file is removed again.
  const std::string folder = (dir / "taken").string();
  ASSERT_EQ(::mkdir(folder.c_str(), 0755), 0);
  EXPECT_TRUE(write_file_atomically(folder, "x\n").has_value());
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken"});
  ::rmdir(folder.c_str());
}

}  // namespace
}  // namespace gen_hazards
