// Options every command shares (--creature, --motor, --dt, --genome, --seed, --precision) and
// the rules for every flag (no empty values, no signed seeds, who runs under mpirun). What the
// options describe and its loading are the run layer's (run/scene.h).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "run/compare_request.h"
#include "run/scene.h"

namespace hexgait {

// `with_allow_long` adds --allow-long (for commands that simulate).
void AddSceneOptions(CLI::App* command, SceneOptions& options, bool with_allow_long = true);

// --genome FILE | --unoptimized (the default), run/scene.h's GenomeChoice.
void AddGenomeOptions(CLI::App* command, GenomeChoice& choice);

// For unsigned flags (--seed): CLI11 would wrap "-1" into 2^64 - 1 and clamp a larger number
// to it; this refuses any sign and anything above 2^64 - 1.
std::string CheckUnsigned64(const std::string& text);
inline const CLI::Validator kNoSign([](std::string& text) { return CheckUnsigned64(text); },
                                    "UINT");
// --seed, with kNoSign and its default shown. Every command's seed goes through this, so
// `--seed -1` is refused alike everywhere (CLI11's exit status 2) instead of wrapping to 2^64 - 1.
CLI::Option* AddSeedOption(CLI::App* command, uint64_t& seed, const std::string& help);

// The choices of --precision, the lanes' number type (simd/isa.h: ParsePrecision).
inline const std::vector<std::string> kPrecisionNames = {"double", "float"};
// --precision NAME, one of kPrecisionNames, default shown; parse it with ParsePrecision.
CLI::Option* AddPrecisionOption(CLI::App* command, std::string& precision, const std::string& help);

// Every option that takes a value refuses an empty one, in every command at once: "" is never a
// valid path, name or number, and `--resume ""` must not quietly mean "no --resume".
void RefuseEmptyValues(CLI::App& app);

// Under mpirun every rank runs the same command line. A command that can spread its work over
// ranks declares it once, at registration; it then runs on every rank, and its evaluator (or
// task pool) keeps the worker ranks busy until rank 0 is done (eval/mpi_evaluator.h). Every
// other command runs on rank 0 only: LeaveMpiWorkersOut, called once after all commands are
// registered, ends it at once on the others.
void Distributed(CLI::App* command);
void LeaveMpiWorkersOut(CLI::App& app);

// --expect FILE, for a command that writes one image or movie: compare what it wrote with FILE
// by the golden-image rule (hexgait compare's defaults).
void AddExpectOption(CLI::App* command, std::string& expect);
// Prints the comparison --expect asked for (nothing without one); a mismatch then ends the
// command with exit status 1, the file written and its diff beside it.
void ReportExpected(const std::optional<CompareResult>& expected);

// A command's verdict as its exit status, for a command whose answer is not "done"
// (`compare`: 1 when the files differ): main returns `status`, having printed nothing more.
struct ExitWith {
  int status;
};

}  // namespace hexgait
