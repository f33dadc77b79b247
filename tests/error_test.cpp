// Error messages stay one printable line whatever bytes the input puts into them.
#include <gtest/gtest.h>

#include "common/error.h"

namespace voxgi {
namespace {

TEST(Error, PrintableEscapesControlsAndInvalidUtf8) {
  EXPECT_EQ(printable("plain text"), "plain text");
  EXPECT_EQ(printable("a\nb\x1b[2J"), "a\\x0ab\\x1b[2J");
  EXPECT_EQ(printable(std::string("nul\0here", 8)), "nul\\x00here");
  EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x86\x92"), "caf\xc3\xa9 \xe2\x86\x92");  // valid UTF-8 kept
  EXPECT_EQ(printable("\xff\xc3"), "\\xff\\xc3");           // invalid, truncated
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(printable("\xc2\x9b"), "\\xc2\\x9b");           // C1 control (CSI)
  EXPECT_EQ(printable(std::string(600, 'a')), std::string(512, 'a') + "...");
}

TEST(Error, InputErrorIsOneLine) {
  const InputError e("scene\n.json", "field\r", "reason\x07");
  EXPECT_STREQ(e.what(), "scene\\x0a.json: field\\x0d: reason\\x07");
}

}  // namespace
}  // namespace voxgi
