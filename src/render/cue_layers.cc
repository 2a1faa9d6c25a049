#include "render/cue_layers.h"

#include <algorithm>
#include <cmath>

#include "render/leg_colours.h"

namespace hexgait {
namespace {

// Cycles over which a footprint and the trail fade into the ground.
constexpr float kFootprintFadeCycles = 4.0f;
constexpr float kTrailFadeCycles = 10.0f;
// Cycles of history the footfall strip shows.
constexpr float kStripCycles = 3.0f;

Eigen::Vector3f Fade(const Eigen::Vector3f& ground, const Eigen::Vector3f& mark, float weight) {
  return ground + weight * (mark - ground);
}

// 1 for a mark made now, falling linearly to 0 after `cycles` gait cycles.
float FadeWeight(const GaitHistory& h, float time, float cycles) {
  return 1.0f - (h.now - time) / (cycles * h.cycle_period);
}

void AddDisc(Mesh& mesh, const Eigen::Vector2f& at, float radius, const Eigen::Vector3f& colour) {
  constexpr int kSides = 12;
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  const Eigen::Vector3f centre(at.x(), at.y(), 0);
  for (int k = 0; k < kSides; ++k) {
    const float a0 = 2.0f * static_cast<float>(M_PI) * k / kSides;
    const float a1 = 2.0f * static_cast<float>(M_PI) * (k + 1) / kSides;
    mesh.Add(centre, up, colour);
    mesh.Add(centre + radius * Eigen::Vector3f(std::cos(a0), std::sin(a0), 0), up, colour);
    mesh.Add(centre + radius * Eigen::Vector3f(std::cos(a1), std::sin(a1), 0), up, colour);
  }
}

Mesh Footprints(const GaitHistory& h, const MeshStyle& look) {
  Mesh mesh;
  mesh.kind = Mesh::Kind::kDecal;
  mesh.vertices.reserve(h.footprints.size() * 12 * 3 * 9);
  // Oldest first, so a fresh footprint lies over an old one.
  for (size_t i = 0; i < h.footprints.size(); ++i) {
    const Footprint& f = h.footprints[i];
    const float w = FadeWeight(h, f.time, kFootprintFadeCycles);
    if (w <= 0) continue;
    const Eigen::Vector3f colour = LegColour(f.leg);
    // A dark rim reads on the checkerboard and tells overlapping prints apart.
    AddDisc(mesh, f.at, h.foot_radius, Fade(look.ground_colour, 0.45f * colour, w));
    AddDisc(mesh, f.at, 0.75f * h.foot_radius, Fade(look.ground_colour, colour, w));
  }
  return mesh;
}

Mesh Trail(const GaitHistory& h, const MeshStyle& look) {
  Mesh mesh;
  mesh.kind = Mesh::Kind::kDecal;
  mesh.vertices.reserve(h.trail.size() * 6 * 9);
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ(), ink(0.25f, 0.25f, 0.28f);
  const float half_width = 0.18f * h.foot_radius;
  for (size_t i = 1; i < h.trail.size(); ++i) {
    const TrailPoint& a = h.trail[i - 1];
    const TrailPoint& b = h.trail[i];
    const float w = FadeWeight(h, b.time, kTrailFadeCycles);
    if (w <= 0) continue;
    const Eigen::Vector2f along = b.at - a.at;
    const float length = along.norm();
    if (length <= 0) continue;
    const Eigen::Vector2f side = Eigen::Vector2f(-along.y(), along.x()) * (half_width / length);
    const Eigen::Vector3f colour = Fade(look.ground_colour, ink, w);
    const auto p = [](const Eigen::Vector2f& v) { return Eigen::Vector3f(v.x(), v.y(), 0); };
    // Overlapping the next segment by the half width closes the gaps at bends.
    const Eigen::Vector2f extend = along * (half_width / length);
    const Eigen::Vector3f q[4] = {p(a.at - side), p(b.at + extend - side), p(b.at + extend + side),
                                  p(a.at + side)};
    for (int k : {0, 1, 2, 0, 2, 3}) mesh.Add(q[k], up, colour);
  }
  return mesh;
}

// Leg polygons whose foot is off the ground take their leg's colour. The creature mesh holds
// BuildMeshes's fan triangulation, 3 (n - 2) vertices per n-gon in polygon order.
void HighlightSwingingLegs(const CreatureModel& model, const std::vector<int>& polygon_legs,
                           const GaitHistory& h, Mesh& solid) {
  size_t vertex = 0;
  for (size_t p = 0; p < model.polygons.size(); ++p) {
    const size_t n = 3 * (model.polygons[p].vertices.size() - 2);
    const int leg = polygon_legs[p];
    if (leg >= 0 && !(h.feet_down >> leg & 1u)) {
      const Eigen::Vector3f colour = LegColour(leg);
      for (size_t v = vertex; v < vertex + n && 9 * v + 8 < solid.vertices.size(); ++v) {
        std::copy_n(colour.data(), 3, &solid.vertices[9 * v + 6]);
      }
    }
    vertex += n;
  }
}

// Blends an RGB colour into a pixel rectangle, clipped to the image.
void FillRect(Image& image, int x0, int y0, int x1, int y1, const Eigen::Vector3f& colour) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
  const uint8_t rgb[3] = {static_cast<uint8_t>(255.0f * colour.x() + 0.5f),
                          static_cast<uint8_t>(255.0f * colour.y() + 0.5f),
                          static_cast<uint8_t>(255.0f * colour.z() + 0.5f)};
  for (int y = y0; y < y1; ++y) {
    uint8_t* p = &image.rgba[(static_cast<size_t>(y) * image.width + x0) * 4];
    for (int x = x0; x < x1; ++x, p += 4) std::copy_n(rgb, 3, p);
  }
}

void Darken(Image& image, int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y) {
    uint8_t* p = &image.rgba[(static_cast<size_t>(y) * image.width + x0) * 4];
    for (int x = x0; x < x1; ++x, p += 4) {
      for (int k = 0; k < 3; ++k) p[k] = static_cast<uint8_t>((p[k] * 2u) / 7u);
    }
  }
}

}  // namespace

void AddSceneCues(const CreatureModel& model, const std::vector<int>& polygon_legs,
                  const GaitHistory& history, const CueOptions& cues, const MeshStyle& look,
                  std::vector<Mesh>& meshes) {
  const auto solid = std::find_if(meshes.begin(), meshes.end(), [](const Mesh& m) {
    return m.kind == Mesh::Kind::kLitTriangles;
  });
  if (solid == meshes.end()) return;
  if (cues.swing) HighlightSwingingLegs(model, polygon_legs, history, *solid);
  // Decals go after the ground and shadow, before the creature (see Mesh::Kind::kDecal).
  ptrdiff_t at = solid - meshes.begin();
  if (cues.trail) meshes.insert(meshes.begin() + at++, Trail(history, look));
  if (cues.footprints) meshes.insert(meshes.begin() + at, Footprints(history, look));
}

FootfallStripLayout FootfallStripLayoutFor(int image_height) {
  FootfallStripLayout layout;
  layout.row_height = std::max(3, image_height / 54);
  // Labels only where they can be read: rows of at least 10 pixels.
  layout.label_pixels = layout.row_height >= 10 ? layout.row_height - 1 : 0;
  return layout;
}

void DrawFootfallStrip(Image& image, const GaitHistory& h, const std::vector<std::string>& labels,
                       const CaptionFont* font) {
  const FootfallStripLayout layout = FootfallStripLayoutFor(image.height);
  const int rows = h.num_legs, row = layout.row_height;
  const int gap = row >= 6 ? 1 : 0;
  const int pad = std::max(2, row / 2);
  const int margin = std::max(4, image.height / 60);
  const int box_x0 = margin, box_x1 = image.width - margin;
  const int box_y1 = image.height - margin, box_y0 = box_y1 - rows * row - 2 * pad;
  Darken(image, box_x0, box_y0, box_x1, box_y1);
  int label_width = 0;
  if (font) {
    for (const std::string& label : labels)
      label_width = std::max(label_width, font->TextWidth(label));
    for (int leg = 0; leg < rows && leg < static_cast<int>(labels.size()); ++leg) {
      const int y = box_y0 + pad + leg * row;
      FillRect(image, box_x0 + pad, y + gap, box_x0 + pad + row / 2, y + row - gap, LegColour(leg));
      font->DrawLine(image, box_x0 + pad + row, y - 1, labels[leg]);
    }
    label_width += row + pad;
  }
  const int x0 = box_x0 + pad + label_width, x1 = box_x1 - pad;
  if (x1 - x0 < 8 || h.strip.empty()) return;
  const float window = kStripCycles * h.cycle_period;
  const float scale = static_cast<float>(x1 - x0) / window;  // pixels per time unit
  const auto x_of = [&](float t) {
    return x1 - static_cast<int>(std::lround((h.now - t) * scale));
  };
  // Sample i stands for the interval since the previous sample; newest first, until the
  // strip's left end.
  for (size_t i = h.strip.size(); i-- > 0;) {
    const FootfallSample& s = h.strip[i];
    const float since = i > 0 ? h.strip[i - 1].time : s.time - 1.0f / scale;
    const int xa = std::max(x0, x_of(since)), xb = x_of(s.time);
    for (int leg = 0; leg < rows; ++leg) {
      if (!(s.feet_down >> leg & 1u)) continue;
      const int y = box_y0 + pad + leg * row;
      FillRect(image, xa, y + gap, std::max(xb, xa + 1), y + row - gap, LegColour(leg));
    }
    if (since <= h.now - window) break;
  }
  // Cycle boundaries, and "now" at the right end.
  const Eigen::Vector3f tick(0.6f, 0.6f, 0.6f), now(1, 1, 1);
  for (float t = std::ceil((h.now - window) / h.cycle_period) * h.cycle_period; t <= h.now;
       t += h.cycle_period) {
    const int x = x_of(t);
    if (x >= x0) FillRect(image, x, box_y0 + pad / 2, x + 1, box_y1 - pad / 2, tick);
  }
  FillRect(image, x1, box_y0 + pad / 2, x1 + std::max(1, row / 5), box_y1 - pad / 2, now);
}

}  // namespace hexgait
