// Libraries opened on demand (util/shared_library.h): a missing one is named with its package.
#include "util/shared_library.h"

#include <gtest/gtest.h>

#include <string>

namespace hexgait {
namespace {

TEST(SharedLibrary, MissingLibraryNamesItsPackage) {
  std::string error;
  EXPECT_EQ(SharedLibrary::Open({"libhexgait_absent.so.7", "libhexgait-absent7"}, &error), nullptr);
  EXPECT_NE(error.find("cannot load libhexgait_absent.so.7 (Debian package libhexgait-absent7)"),
            std::string::npos)
      << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
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
