// Libraries opened on demand (util/shared_library.h): a missing one is named with its package.
#include "util/shared_library.h"

#include <gtest/gtest.h>

#include <string>

namespace hexgait {
namespace {

TEST(SharedLibrary, MissingLibraryNamesItsPackage) {
  std::string error;
  EXPECT_EQ(SharedLibrary::Open({"libhexgait_absent.so.7", "libhexgait-absent7"}, &error), nullptr);
  EXPECT_EQ(error, "libhexgait_absent.so.7 (Debian package libhexgait-absent7) is not installed");
}

// A library that is there but fails to load is not called missing: the message names the file
// that failed, a dependency of it or its own damaged file (tests/cli/runtime_needs_test.sh
// makes both for real).
TEST(SharedLibrary, ABrokenLibraryIsNotCalledMissing) {
  const LibraryName png{"libpng16.so.16", "libpng16-16"};
  EXPECT_EQ(DescribeLoadFailure(
                png, "libz.so.1: cannot open shared object file: No such file or directory"),
            "libpng16.so.16 (Debian package libpng16-16) is installed but cannot be loaded: it "
            "needs libz.so.1, which is missing");
  EXPECT_EQ(DescribeLoadFailure(png, "/opt/lib/libpng16.so.16: file too short"),
            "libpng16.so.16 (Debian package libpng16-16) is installed but cannot be loaded: "
            "/opt/lib/libpng16.so.16: file too short");
}

TEST(SharedLibrary, OpensOnceAndFindsSymbols) {
  std::string error;
  const SharedLibrary* libm = SharedLibrary::Open({"libm.so.6", "libc6"}, &error);
  ASSERT_NE(libm, nullptr) << error;
  EXPECT_EQ(SharedLibrary::Open({"libm.so.6", "libc6"}, &error), libm);
  double (*cosine)(double) = nullptr;
  ASSERT_TRUE(libm->Bind("cos", cosine, &error)) << error;
  EXPECT_EQ(cosine(0.0), 1.0);
  EXPECT_FALSE(libm->Bind("hexgait_no_such_symbol", cosine, &error));
  EXPECT_NE(error.find("hexgait_no_such_symbol"), std::string::npos) << error;
}

TEST(SharedLibrary, MissingModuleSaysSo) {
  std::string error;
  EXPECT_EQ(SharedLibrary::OpenModule("libhexgait_absent_module.so", &error), nullptr);
  EXPECT_NE(error.find("libhexgait_absent_module.so is not installed beside hexgait"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace hexgait
