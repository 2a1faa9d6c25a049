// The movie's colour conversion against the BT.709 formula in double precision and against
// libswscale's BT.709 conversion of the same image.
#include "encode/yuv_convert.h"

#include <gtest/gtest.h>

extern "C" {
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace hexgait {
namespace {

constexpr int kW = 96, kH = 64;

// Smooth gradients with hard-edged blocks: what rendered frames are made of.
std::vector<uint8_t> TestImage(bool blocks = true) {
  std::vector<uint8_t> rgba(kW * kH * 4);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      uint8_t* p = &rgba[(y * kW + x) * 4];
      const bool block = blocks && ((x / 12) + (y / 10)) % 3 == 0;
      p[0] = block ? 250 : static_cast<uint8_t>(x * 255 / (kW - 1));
      p[1] = block ? 20 : static_cast<uint8_t>(y * 255 / (kH - 1));
      p[2] = static_cast<uint8_t>((x * 7 + y * 3) % 256);
      p[3] = 255;
    }
  }
  return rgba;
}

struct Planes {
  std::vector<uint8_t> y = std::vector<uint8_t>(kW * kH);
  std::vector<uint8_t> u = std::vector<uint8_t>(kW * kH / 4);
  std::vector<uint8_t> v = std::vector<uint8_t>(kW * kH / 4);
};

Planes Convert(const std::vector<uint8_t>& rgba) {
  Planes out;
  RgbaToYuv420(rgba.data(), 4 * kW, kW, kH, out.y.data(), kW, out.u.data(), kW / 2, out.v.data(),
               kW / 2);
  return out;
}

TEST(YuvConvert, MatchesTheBt709FormulaToTheLevel) {
  const std::vector<uint8_t> rgba = TestImage();
  const Planes got = Convert(rgba);
  const double kr = 0.2126, kb = 0.0722, kg = 1 - kr - kb;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const uint8_t* p = &rgba[(y * kW + x) * 4];
      const double luma = 16 + (kr * p[0] + kg * p[1] + kb * p[2]) * 219 / 255;
      ASSERT_LE(std::abs(got.y[y * kW + x] - luma), 0.51) << x << "," << y;
    }
  }
  for (int y = 0; y < kH / 2; ++y) {
    for (int x = 0; x < kW / 2; ++x) {
      double r = 0, g = 0, b = 0;
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          const uint8_t* p = &rgba[((2 * y + dy) * kW + 2 * x + dx) * 4];
          r += p[0] / 4.0, g += p[1] / 4.0, b += p[2] / 4.0;
        }
      }
      const double luma = kr * r + kg * g + kb * b;
      const double u = 128 + (b - luma) / (2 * (1 - kb)) * 224 / 255;
      const double v = 128 + (r - luma) / (2 * (1 - kr)) * 224 / 255;
      ASSERT_LE(std::abs(got.u[y * kW / 2 + x] - u), 0.51) << x << "," << y;
      ASSERT_LE(std::abs(got.v[y * kW / 2 + x] - v), 0.51) << x << "," << y;
    }
  }
}

TEST(YuvConvert, AgreesWithSwscale) {
  // Gradients only: at a sharp edge swscale's wider chroma filter differs from a 2x2 average.
  const std::vector<uint8_t> rgba = TestImage(false);
  const Planes got = Convert(rgba);
  Planes ref;
  SwsContext* sws = sws_getContext(kW, kH, AV_PIX_FMT_RGBA, kW, kH, AV_PIX_FMT_YUV420P,
                                   SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
  ASSERT_NE(sws, nullptr);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  const uint8_t* src[1] = {rgba.data()};
  const int src_stride[1] = {4 * kW};
  uint8_t* dst[3] = {ref.y.data(), ref.u.data(), ref.v.data()};
  const int dst_stride[3] = {kW, kW / 2, kW / 2};
  sws_scale(sws, src, src_stride, 0, kH, dst, dst_stride);
  sws_freeContext(sws);
  int worst_y = 0;
  double mean_chroma = 0;
  for (size_t i = 0; i < got.y.size(); ++i)
    worst_y = std::max(worst_y, std::abs(got.y[i] - ref.y[i]));
  for (size_t i = 0; i < got.u.size(); ++i) {
    mean_chroma += std::abs(got.u[i] - ref.u[i]) + std::abs(got.v[i] - ref.v[i]);
  }
  mean_chroma /= 2.0 * got.u.size();
  EXPECT_LE(worst_y, 1);  // the same matrix and range
  // Chroma: swscale filters each 2x2 block with a wider kernel, so sharp edges differ a little.
  EXPECT_LT(mean_chroma, 2.0);
}

}  // namespace
}  // namespace hexgait
