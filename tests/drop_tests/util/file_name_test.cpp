// Names that become parts of file names: one check refuses every name that could lead a write out
// of its output folder or make an unwritable file name.
#include "drop_tests/util/file_name.h"

#include <gtest/gtest.h>

#include <string>

namespace touchdown::io {
namespace {

TEST(FileName, PlainNamesPass) {
  EXPECT_EQ(FileNameProblem("name", "flat"), "");
  EXPECT_EQ(FileNameProblem("name", "fjs1_lp.v2-final"), "");
  EXPECT_EQ(FileNameProblem("name", "caf\xC3\xA9"), "");
  EXPECT_EQ(FileNameProblem("name", "..."), "");  // a name, not the parent folder
  EXPECT_EQ(FileNameProblem("name", std::string(kMaxNameBytes, 'a')), "");
}

TEST(FileName, NamesThatLeaveTheFolderAreRefused) {
  EXPECT_EQ(FileNameProblem("", "../../../PWNED"), "'../../../PWNED' contains '/' (it names files)");
  EXPECT_EQ(FileNameProblem("", "/some/dir/ABS"), "'/some/dir/ABS' contains '/' (it names files)");
  EXPECT_EQ(FileNameProblem("", "a\\b"), "'a\\b' contains '\\' (it names files)");
  EXPECT_EQ(FileNameProblem("", ".."), "'..' cannot be a file name");
  EXPECT_EQ(FileNameProblem("", "."), "'.' cannot be a file name");
}

TEST(FileName, EmptyLongAndControlBytesAreRefused) {
  EXPECT_EQ(FileNameProblem("", ""), "must not be empty");
  EXPECT_EQ(FileNameProblem("drop id", ""), "empty drop id");
  EXPECT_EQ(FileNameProblem("", std::string(kMaxNameBytes + 1, 'a')), "longer than 200 bytes (it names files)");
  EXPECT_EQ(FileNameProblem("", "a\nb"), "contains a control character (it names files)");
  EXPECT_EQ(FileNameProblem("", std::string("a\0b", 3)), "contains a control character (it names files)");
  EXPECT_EQ(FileNameProblem("", "a\x7f"), "contains a control character (it names files)");
  EXPECT_EQ(FileNameProblem("drop id", "a/b"), "drop id 'a/b' contains '/' (it names files)");
}

}  // namespace
}  // namespace touchdown::io
