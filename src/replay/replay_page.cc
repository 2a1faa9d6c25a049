#include "replay/replay_page.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "embedded_replay.h"
#include "embedded_shaders.h"
#include "render/cue_layers.h"
#include "render/leg_colours.h"
#include "util/html_text.h"

namespace hexgait {
namespace {

using nlohmann::json;

json Vec(const Eigen::Vector3f& v) {
  return json::array({v.x(), v.y(), v.z()});
}

template <typename T>
std::string Packed(const std::vector<T>& values) {
  return Base64(values.data(), values.size() * sizeof(T));
}

json CreatureJson(const CreatureModel& model) {
  json polygons = json::array(), skin = json::array(), springs = json::array();
  for (const Polygon& p : model.polygons) {
    polygons.push_back({{"v", p.vertices}, {"leg", p.is_leg}});
  }
  for (const SkinVertex& s : model.skin_vertices) {
    json blend = json::array();
    for (const auto& [particle, weight] : s.blend) blend.push_back({particle, weight});
    skin.push_back(blend);
  }
  for (int s = 0; s < model.num_springs(); ++s) {
    if (model.spring_cut(s)) continue;  // a lost leg's
    springs.push_back({model.spring_a[s], model.spring_b[s], model.spring_motor[s] ? 1 : 0});
  }
  // Which leg each polygon belongs to, for the swinging-leg cue, as the movies decide it.
  const std::vector<int> polygon_legs = PolygonLegs(model);
  json legs = json::array();
  for (size_t i = 0; i < model.legs.size(); ++i) {
    std::string name = model.legs[i].name;
    for (char& c : name) c = c == '_' ? ' ' : c;
    const bool damaged = !model.leg_damaged.empty() && model.leg_damaged[i];
    const bool lost = model.lost_legs >> i & 1u;
    legs.push_back({{"name", name},
                    {"colour", Vec(LegColour(static_cast<int>(i)))},
                    {"damaged", damaged},
                    {"lost", lost}});
  }
  // A lost leg's foot: a loose particle, not drawn (as in the movies).
  json loose = json::array();
  for (int i = 0; i < model.num_particles(); ++i) {
    if (model.particle_loose(i)) loose.push_back(i);
  }
  return {{"name", model.name},           {"particles", model.num_particles()},
          {"loose_particles", loose},     {"polygons", polygons},
          {"polygon_legs", polygon_legs}, {"skin", skin},
          {"springs", springs},           {"legs", legs}};
}

json CameraJson(const CameraSpec& spec) {
  return {{"eye", Vec(spec.eye_offset)},
          {"target", Vec(spec.target_offset)},
          {"fov", spec.fov_y},
          {"tracking", TrackingName(spec.tracking)}};
}

// Replaces the one `marker` in `page` with `text`; the template and this code must agree.
void Fill(std::string& page, const std::string& marker, const std::string& text) {
  const size_t at = page.find(marker);
  if (at == std::string::npos) throw std::logic_error("replay template lacks " + marker);
  page.replace(at, marker.size(), text);
}

}  // namespace

std::string Base64(const void* data, size_t size) {
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const unsigned v = bytes[i] << 16 | bytes[i + 1] << 8 | bytes[i + 2];
    out += {kDigits[v >> 18], kDigits[v >> 12 & 63], kDigits[v >> 6 & 63], kDigits[v & 63]};
  }
  if (i + 1 == size) {
    const unsigned v = bytes[i] << 16;
    out += {kDigits[v >> 18], kDigits[v >> 12 & 63], '=', '='};
  } else if (i + 2 == size) {
    const unsigned v = bytes[i] << 16 | bytes[i + 1] << 8;
    out += {kDigits[v >> 18], kDigits[v >> 12 & 63], kDigits[v >> 6 & 63], '='};
  }
  return out;
}

std::string ReplayPage(const CreatureModel& model, const ReplayRecording& recording,
                       const ReplayPageOptions& options) {
  json presets = json::array();
  for (const CameraPreset& preset : CameraPresets()) {
    CameraSpec spec = preset.spec;
    if (options.preset_fov > 0) spec.fov_y = options.preset_fov;
    json p = CameraJson(spec);
    p["name"] = preset.name;
    p["description"] = preset.description;
    presets.push_back(p);
  }
  std::vector<float> prints, trail;
  for (const Footprint& f : recording.footprints) {
    prints.insert(prints.end(), {f.time, f.at.x(), f.at.y(), static_cast<float>(f.leg)});
  }
  for (const TrailPoint& t : recording.trail)
    trail.insert(trail.end(), {t.time, t.at.x(), t.at.y()});
  const MeshStyle& look = options.look;
  const RunResult& r = recording.result;
  const json data = {
      {"format", "hexgait replay 1"},
      {"title", options.title},
      {"summary", options.summary},
      {"creature", CreatureJson(model)},
      {"look",
       {{"body", Vec(look.body_colour)},
        {"leg", Vec(look.leg_colour)},
        {"damaged_leg", Vec(look.damaged_leg_colour)},
        {"ground", Vec(look.ground_colour)},
        {"background", Vec(look.lighting.background)},
        {"light", Vec(look.lighting.direction)},
        {"ambient", look.lighting.ambient},
        {"overlay", look.overlay},
        {"shadow", look.shadow},
        {"foot_radius", recording.foot_radius}}},
      {"cues",
       {{"footprints", options.cues.footprints},
        {"trail", options.cues.trail},
        {"swing", options.cues.swing},
        {"strip", options.cues.strip}}},
      {"presets", presets},
      {"view", options.view},
      {"camera", CameraJson(options.camera)},
      {"run",
       {{"duration", options.duration},
        {"dt", options.dt},
        {"cycle_period", options.cycle_period},
        {"stride", recording.stride},
        {"frames", recording.frames()},
        {"distance", r.distance},
        {"fell", r.fell},
        {"fall_time", r.fall_time}}},
      {"frames",
       {{"time", Packed(recording.time)},
        {"position", Packed(recording.position)},
        {"centre", Packed(recording.centre)},
        {"follow", Packed(recording.follow)},
        {"feet_down", Packed(recording.feet_down)}}},
      {"footprints", Packed(prints)},
      {"trail", Packed(trail)},
      {"shaders", {{"vertex", kShader_creature_vert}, {"fragment", kShader_creature_frag}}},
  };
  std::string page = kReplay_page_html;
  Fill(page, "<!--TITLE-->", HtmlEscape("hexgait replay: " + options.title));
  Fill(page, "/*STYLE*/", kReplay_replay_css);
  Fill(page, "/*SCRIPT*/", kReplay_replay_js);
  Fill(page, "/*DATA*/", ScriptJson(data.dump()));  // last: no later marker is searched in it
  return page;
}

}  // namespace hexgait
