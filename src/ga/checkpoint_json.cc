#include "ga/checkpoint_json.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "sim/integrator.h"
#include "simd/isa.h"
#include "util/error.h"

namespace hexgait {

using nlohmann::json;

json Number(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}

double ReadNumber(const JsonReader& r, const std::string& key) {
  const JsonReader value = r.Child(key);
  if (value.value().is_number()) return value.value().get<double>();
  if (value.value().is_string()) {
    const std::string s = value.value().get<std::string>();
    if (s == "inf") return INFINITY;
    if (s == "-inf") return -INFINITY;
    if (s == "nan") return NAN;
  }
  r.Fail("'" + key + "' must be a number");
}

long long ReadInteger64(const JsonReader& r, const std::string& key) {
  const JsonReader value = r.Child(key);
  if (!value.value().is_number_integer()) r.Fail("'" + key + "' must be an integer");
  if (value.value().is_number_unsigned() &&
      value.value().get<unsigned long long>() > std::numeric_limits<long long>::max()) {
    r.Fail("'" + key + "' is out of range");
  }
  return value.value().get<long long>();
}

uint64_t ReadSeed(const JsonReader& r) {
  const std::string seed = r.String("seed");
  uint64_t value = 0;
  const auto parsed = std::from_chars(seed.data(), seed.data() + seed.size(), value);
  if (parsed.ec != std::errc() || parsed.ptr != seed.data() + seed.size()) {
    r.Fail("'seed' must be a decimal integer in a string");
  }
  return value;
}

json ResultJson(const RunResult& r) {
  return {{"distance", Number(r.distance)},
          {"fell", r.fell},
          {"fall_time", Number(r.fall_time)},
          {"fall_cycle", r.fall_cycle},
          {"steps", r.steps},
          {"end_time", Number(r.end_time)},
          {"diverged", r.diverged},
          {"diverge_time", Number(r.diverge_time)},
          {"diverge_step", r.diverge_step},
          {"diverge_reason", r.diverge_reason},
          {"min_body_height", Number(r.min_body_height)},
          {"max_tilt_degrees", Number(r.max_tilt_degrees)},
          {"mean_feet_on_ground", Number(r.mean_feet_on_ground)},
          {"feet_samples", r.feet_samples},
          {"foot_down_checks", r.foot_down_checks}};
}

RunResult ReadResult(const JsonReader& r) {
  r.RequireOnlyKeys({"distance", "fell", "fall_time", "fall_cycle", "steps", "end_time", "diverged",
                     "diverge_time", "diverge_step", "diverge_reason", "min_body_height",
                     "max_tilt_degrees", "mean_feet_on_ground", "feet_samples",
                     "foot_down_checks"});
  RunResult out;
  out.distance = ReadNumber(r, "distance");
  out.fell = r.Bool("fell");
  out.fall_time = ReadNumber(r, "fall_time");
  out.fall_cycle = r.Integer("fall_cycle");
  out.steps = ReadInteger64(r, "steps");
  out.end_time = ReadNumber(r, "end_time");
  out.diverged = r.Bool("diverged");
  out.diverge_time = ReadNumber(r, "diverge_time");
  out.diverge_step = ReadInteger64(r, "diverge_step");
  out.diverge_reason = r.String("diverge_reason");
  out.min_body_height = ReadNumber(r, "min_body_height");
  out.max_tilt_degrees = ReadNumber(r, "max_tilt_degrees");
  out.mean_feet_on_ground = ReadNumber(r, "mean_feet_on_ground");
  out.feet_samples = ReadInteger64(r, "feet_samples");
  // Checkpoints from before duty factors were counted have none: zeros.
  if (r.value().contains("foot_down_checks")) {
    const JsonReader counts = r.Child("foot_down_checks");
    if (counts.ArraySize() != out.foot_down_checks.size()) {
      counts.Fail("expected " + std::to_string(out.foot_down_checks.size()) + " counts");
    }
    for (size_t leg = 0; leg < out.foot_down_checks.size(); ++leg) {
      const JsonReader count = counts.At(leg);
      if (!count.value().is_number_integer() || count.value().get<long long>() < 0) {
        count.Fail("must be a whole number of checks");
      }
      out.foot_down_checks[leg] = count.value().get<long long>();
    }
  }
  return out;
}

void AddRunOptionsJson(json& params, const RunOptions& run, Precision precision) {
  params["time"] = run.duration;
  params["dt"] = run.dt;
  params["integrator"] = IntegratorName(run.integrator);
  params["check_interval"] = run.check_interval;
  params["divergence_speed"] = run.divergence_speed;
  params["early_stop"] = run.early_stop;
  if (run.stop_at_fall) params["stop_at_fall"] = true;
  params["rest_kinetic_energy"] = run.rest_kinetic_energy;
  params["precision"] = PrecisionName(precision);
}

void ReadRunOptionsJson(const JsonReader& r, RunOptions* run, Precision* precision) {
  run->duration = r.PositiveNumber("time");
  run->dt = r.PositiveNumber("dt");
  try {
    run->integrator = ParseIntegrator(r.String("integrator"));
  } catch (const InputError& e) {
    r.Fail(e.what());
  }
  run->check_interval = r.Integer("check_interval");
  if (run->check_interval < 1) r.Fail("'check_interval' must be at least 1");
  run->divergence_speed = r.PositiveNumber("divergence_speed");
  run->early_stop = r.Bool("early_stop");
  run->stop_at_fall = r.Has("stop_at_fall") && r.Bool("stop_at_fall");
  run->rest_kinetic_energy = r.PositiveNumber("rest_kinetic_energy");
  *precision = Precision::kDouble;
  if (r.Has("precision")) {
    const std::string name = r.String("precision");
    try {
      *precision = ParsePrecision(name);
    } catch (const InputError&) {
      r.Fail("'precision' must be \"double\" or \"float\"");  // with the file's context
    }
  }
}

std::string Hex(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

void AddFormatHeader(json& root, const char* format, int format_version) {
  root["format"] = format;
  root["format_version"] = format_version;
  root["hexgait_version"] = HEXGAIT_VERSION;
}

std::vector<std::string> FormatHeaderKeys() {
  return {"format", "format_version", "hexgait_version", "version"};
}

int ReadFormatVersion(const JsonReader& r) {
  const bool current = r.Has("format_version"), old = r.Has("version");
  if (current && old) r.Fail("has both 'format_version' and 'version'");
  if (r.Has("hexgait_version")) r.String("hexgait_version");
  return r.Integer(old ? "version" : "format_version");
}

std::string Checksum(json root) {
  root.erase("checksum");
  const std::string body = root.dump();
  Fingerprint f;
  f.Add(body.data(), body.size());
  return Hex(f.value());
}

}  // namespace hexgait
