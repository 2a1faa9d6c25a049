// JSON pieces shared by the resumable files of the evolution layer (the GA's checkpoint,
// ga/checkpoint.h, and the MAP-Elites archive, ga/map_elites_checkpoint.h): exact doubles,
// run results, the FNV-1a fingerprint and the checksum that refuses an edited file.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/batch_kernel.h"
#include "sim/step_loop.h"
#include "util/json_file.h"

namespace hexgait {

// FNV-1a over raw bytes: stable across machines for the same values.
class Fingerprint {
 public:
  void Add(const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 0x100000001B3ULL;
  }
  void Add(double v) { Add(&v, sizeof v); }
  void Add(long long v) { Add(&v, sizeof v); }
  void Add(const std::string& s) {
    Add(static_cast<long long>(s.size()));
    Add(s.data(), s.size());
  }
  template <class T>
  void AddAll(const std::vector<T>& values) {
    Add(static_cast<long long>(values.size()));
    for (const T& v : values) Add(static_cast<double>(v));
  }
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = 0xCBF29CE484222325ULL;
};

// Non-finite doubles are not JSON numbers: they are written as the strings "nan", "inf" and
// "-inf", and read back by ReadNumber.
nlohmann::json Number(double v);
double ReadNumber(const JsonReader& r, const std::string& key);
long long ReadInteger64(const JsonReader& r, const std::string& key);
// "seed": a 64-bit seed as a decimal string (a JSON number would lose bits above 2^53).
uint64_t ReadSeed(const JsonReader& r);

// Every field of a RunResult, exactly.
nlohmann::json ResultJson(const RunResult& r);
RunResult ReadResult(const JsonReader& r);

// The run options (time, dt, integrator, checks, early stop, precision) as members of a
// parameters object, and back; a file without "precision" ran in double (written before float
// lanes), one without "stop_at_fall" ran to the end.
void AddRunOptionsJson(nlohmann::json& params, const RunOptions& run, Precision precision);
void ReadRunOptionsJson(const JsonReader& r, RunOptions* run, Precision* precision);

// The header of every resumable file: its "format", the "format_version" of that format and
// the "hexgait_version" of the program that wrote it (files written before these keys name the
// format's version "version" and have no program version; they still read).
void AddFormatHeader(nlohmann::json& root, const char* format, int format_version);
// The header's keys, for RequireOnlyKeys: "format", "format_version", "hexgait_version" and the
// older "version".
std::vector<std::string> FormatHeaderKeys();
// The format's version: "format_version", or "version" in an older file; fails when neither or
// both are there. (The format itself is checked by the caller.)
int ReadFormatVersion(const JsonReader& r);

// 16 lower-case hex digits.
std::string Hex(uint64_t v);
// The checksum of a file's JSON: FNV-1a over the compact dump of everything but its
// "checksum" member. nlohmann::json keeps object keys sorted and prints doubles in their
// shortest round-trip form, so parsing and dumping again gives the same bytes.
std::string Checksum(nlohmann::json root);

}  // namespace hexgait
