// The workspace index of the language server (lsp/program_index.h): what
// it finds in library files, and the files it must not wait on.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lsp/program_index.h"

namespace mbc::lsp {
namespace {

TEST(LspProgramIndex, ProgramsOfALibraryFileAndRefresh) {
  const auto dir =
      std::filesystem::temp_directory_path() / "mbc_index_test_library";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / ".git");
  std::ofstream(dir / "lib.nc") << "%\nO9010(A)\nM99\n<DRILL>(B)\nM99\n%\n";
  std::ofstream(dir / ".git" / "O9020.nc") << "O9020\nM99\n";
  std::ofstream(dir / "empty.nc");
  ProgramIndex index;
  index.scan({dir.string()});
  EXPECT_EQ(index.fileOf({9010, "O9010"}), (dir / "lib.nc").string());
  EXPECT_EQ(index.matching("DRI", 10).size(), 1U);
  EXPECT_FALSE(index.fileOf({9020, "O9020"})) << "a hidden folder is skipped";
  std::ofstream(dir / "lib.nc") << "%\nO9011\nM99\n%\n";
  index.refresh((dir / "lib.nc").string());
  EXPECT_FALSE(index.fileOf({9010, "O9010"}));
  EXPECT_TRUE(index.fileOf({9011, "O9011"}));
  std::filesystem::remove_all(dir);
}

TEST(LspProgramIndex, AFileThatSaysItIsEmptyIsNotRead) {
  // /proc/kmsg is a regular file of size 0 whose read waits for the
  // kernel's next message (for root): a workspace at / must not hang on it.
  if (!std::filesystem::is_regular_file("/proc/kmsg")) {
    GTEST_SKIP() << "no /proc/kmsg here";
  }
  ProgramIndex index;
  index.refresh("/proc/kmsg");
  EXPECT_TRUE(index.matching("", 10).empty());
}

} // namespace
} // namespace mbc::lsp
