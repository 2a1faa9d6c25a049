// hexgait: reproduces Nikovski's evolved hexapod gait and turns it into movies and figures.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "app/cli_common.h"
#include "app/commands.h"
#include "eval/mpi_evaluator.h"
#include "render/gl_context.h"
#include "util/error.h"
#include "util/stop_signal.h"

namespace {

int Main(int argc, char** argv) {
  hexgait::InstallStopHandlers();  // first: a signal before this would take the default action
  CLI::App app{
      "hexgait: a six-legged mass-spring creature walks under an open-loop motor program, and a\n"
      "genetic algorithm evolves the program's rest lengths (Nikovski, 'Evolving Legged\n"
      "Locomotion of Virtual Creatures').\n\n"
      "Start with:\n"
      "  hexgait simulate --unoptimized     watch the hand-made program fall\n"
      "  hexgait evolve --seed 1            evolve it with the paper's settings (out/run/)\n"
      "  hexgait simulate --genome out/run/best.genome\n"
      "  hexgait movie --run out/run        gait movies of both programs (out/*.mp4)\n"
      "Run 'hexgait COMMAND --help' for a command's options."};
  // The GL line makes a context, so it names the backend and renderer frames would really use.
  app.set_version_flag("--version", [] {
    std::string error;
    const auto context = hexgait::GlContext::Create(&error);
    return std::string(HEXGAIT_VERSION) +
           (hexgait::MpiBuiltIn() ? " (MPI built in)" : " (without MPI)") +
           "\nOpenGL: " + (context ? context->Describe() : "none (" + error + ")");
  });
  app.require_subcommand(1);
  hexgait::RegisterSimulate(app);
  hexgait::RegisterEvolve(app);
  hexgait::RegisterSweep(app);
  hexgait::RegisterEndurance(app);
  hexgait::RegisterRepertoire(app);
  hexgait::RegisterInspect(app);
  hexgait::RegisterStill(app);
  hexgait::RegisterFilmstrip(app);
  hexgait::RegisterRender(app);
  hexgait::RegisterMovie(app);
  hexgait::RegisterBench(app);
  hexgait::RegisterFigures(app);
  hexgait::RegisterReport(app);
  hexgait::RegisterReplay(app);
  hexgait::RegisterAdapt(app);
  hexgait::RegisterCompare(app);
  hexgait::RefuseEmptyValues(app);
  hexgait::LeaveMpiWorkersOut(app);
  hexgait::StartStopWatchdog();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) {
      std::string message = e.what();
      for (char& c : message) c = c == '\n' ? ' ' : c;
      std::fprintf(stderr, "hexgait: error: %s (see 'hexgait --help')\n", message.c_str());
      return 2;
    }
    return app.exit(e);
  } catch (const hexgait::ExitWith& verdict) {
    return verdict.status;
  } catch (const hexgait::MpiWorkerDone&) {
    return 0;  // a worker rank's share of the command is done (or it had none)
  } catch (const hexgait::Stopped& e) {
    std::fprintf(stderr, "hexgait: stopped by %s: %s\n", hexgait::StopSignalName().c_str(),
                 e.what());
    return hexgait::StopExitCode();
  } catch (const hexgait::InputError& e) {
    hexgait::AwaitStopWatchdog();
    std::fprintf(stderr, "hexgait: error: %s\n", e.what());
    return 1;
  } catch (const hexgait::SystemError& e) {
    // The input was fine; this machine could not do the work (docs/errors.md, exit status).
    hexgait::AwaitStopWatchdog();
    std::fprintf(stderr, "hexgait: error: %s\n", e.what());
    return 4;
  } catch (const std::exception& e) {
    hexgait::AwaitStopWatchdog();
    std::fprintf(stderr, "hexgait: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    hexgait::MpiInitIfLaunched(&argc, &argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hexgait: error: %s\n", e.what());
    return 1;
  }
  const int code = Main(argc, argv);
  // Rank 0 failed while the others may wait for work: stop the job rather than hang.
  if (code != 0 && hexgait::MpiWorldSize() > 1) hexgait::MpiAbort(code);
  hexgait::MpiFinalize();
  return code;
}
