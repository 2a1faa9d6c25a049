#include "sim/step_loop.h"

namespace hexgait {
namespace {

template <class Stepper>
class ResumableRunOf final : public ResumableRun {
 public:
  ResumableRunOf(const CreatureModel& model, MotorController& controller, SimState& state,
                 const RunOptions& options)
      : run_(model, controller, state, options) {}
  bool Advance(long long steps) override {
    NullObserver none;
    return run_.Advance(steps, none);
  }
  const RunResult& result_so_far() const override { return run_.result_so_far(); }
  RunResult Finish() override { return run_.Finish(); }

 private:
  SteppedRun<Stepper> run_;
};

}  // namespace

int CheckIntervalFor(double dt) {
  return std::max(1, static_cast<int>(std::lround(0.1 / dt)));
}

std::unique_ptr<ResumableRun> StartRun(const CreatureModel& model, MotorController& controller,
                                       SimState& state, const RunOptions& options) {
  return WithStepperType(options.integrator, [&]<class Stepper>() -> std::unique_ptr<ResumableRun> {
    return std::make_unique<ResumableRunOf<Stepper>>(model, controller, state, options);
  });
}

}  // namespace hexgait
