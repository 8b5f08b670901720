// The stop rules (internal/flow/stop/) on made-up progress, each against what its criterion says:
//  - Paper_criteria: (27) the rate of F = value / F0 relative to the first step's, (28) the rate itself,
//    (29) the largest motion off the input; none from the first step on for (27); (29) off on a fixed surface;
//  - Steady_state: the step's motion per unit of time below the speed;
//  - Noise_level: a cut step ends where it was cut; an uncut one that passed the target ends where the secant
//    between the two distances reaches it, rewound; below the target nothing;
//  - Noise_removed (fourth order): the displacement's relative growth below time_step / (16 h^4), h scaled by
//    the strength above 1; Held_by_bound: growth below 1% of the displacement, under a bound only;
//  - Cramped_flow: four accepted steps in a row at 1/16 of the time step or less;
//  - Stop_rules: the first rule that answers wins and the later ones are not asked;
//  - new_folds: more folds than the input's fall back, or fail when no step had no more.

#include <CGAL/Anisotropic_fairing/internal/flow/stop/New_folds.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rules.h>

#include "test_support/check.h"

#include <cmath>
#include <string>

namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

struct Progress
{
  AF::Fairing_step step;
  AFI::Step_controller control;
  std::string why = "folded";
  double dt = 1, value = 1, max_relative = 0, moved_relative = 1, before = 0, discrepancy = 0, target = 0, cut_at = -1;

  AFI::Step_progress get() const
  {
    return AFI::Step_progress{ step, dt, value, max_relative, moved_relative, before, discrepancy, target, cut_at, control, why };
  }
};

AFI::Stop_rule_setup setup(const AFI::Stepper_settings& s, bool noise = false, bool bound = false, bool fixed = false)
{
  return AFI::Stop_rule_setup{ s, fixed, noise, bound, 10.0, 0.5 };
}

void paper_criteria()
{
  AFI::Stepper_settings s;
  s.stopping = AF::Stopping_criteria::none();
  s.stopping.curvature_rate_ratio = 0.1;
  AFI::Paper_criteria ratio(setup(s));
  Progress p;
  p.step.step = 1; p.value = 9;   // F: 1 -> 0.9, rate -0.1
  AF_CHECK(!ratio.after_step(p.get()), "(27) never on the first step");
  p.step.step = 2; p.value = 8.95;   // rate -0.005: 0.05 of the first
  const auto r = ratio.after_step(p.get());
  AF_CHECK(r && r->reason == AF::Stop_reason::CURVATURE_RATE_RATIO, "(27): the rate fell to 5% of the first");

  s.stopping = AF::Stopping_criteria::none();
  s.stopping.curvature_rate = 0.02;
  AFI::Paper_criteria rate(setup(s));
  p.step.step = 1; p.value = 9; p.dt = 2;   // rate -0.05
  AF_CHECK(!rate.after_step(p.get()), "(28): a rate of 0.05 goes on");
  p.step.step = 2; p.value = 8.9;   // rate -0.005
  const auto q = rate.after_step(p.get());
  AF_CHECK(q && q->reason == AF::Stop_reason::CURVATURE_RATE, "(28): a rate of 0.005 stops");

  s.stopping = AF::Stopping_criteria::none();
  s.stopping.displacement = 0.2;
  p.max_relative = 0.2;
  const auto d = AFI::Paper_criteria(setup(s)).after_step(p.get());
  AF_CHECK(d && d->reason == AF::Stop_reason::DISPLACEMENT, "(29): moved by the threshold");
  AF_CHECK(!AFI::Paper_criteria(setup(s, false, false, true)).after_step(p.get()), "(29) does not apply on a fixed surface");
  p.max_relative = 0.19;
  AF_CHECK(!AFI::Paper_criteria(setup(s)).after_step(p.get()), "(29): short of the threshold");
}

void steady_state()
{
  AFI::Stepper_settings s;
  s.stopping = AF::Stopping_criteria::none();
  s.stopping.steady_speed = 1e-3;
  Progress p;
  p.dt = 10; p.moved_relative = 0.01;   // speed 1e-3
  const auto r = AFI::Steady_state(setup(s)).after_step(p.get());
  AF_CHECK(r && r->reason == AF::Stop_reason::STEADY_STATE, "steady at the speed");
  p.moved_relative = 0.011;
  AF_CHECK(!AFI::Steady_state(setup(s)).after_step(p.get()), "not steady above it");
}

void noise_level()
{
  AFI::Stepper_settings s;
  const AFI::Noise_level rule(setup(s, true));
  Progress p;
  p.target = 1; p.before = 0.5; p.discrepancy = 0.9;
  AF_CHECK(!rule.after_step(p.get()), "short of the noise level: on");
  p.discrepancy = 1.5;   // the secant reaches 1 halfway
  auto r = rule.after_step(p.get());
  AF_CHECK(r && r->reason == AF::Stop_reason::NOISE_LEVEL && std::abs(r->at - 0.5) < 1e-15 && r->rewind,
           "passed within the step: ends halfway, rewound");
  p.cut_at = 0.3;
  r = rule.after_step(p.get());
  AF_CHECK(r && r->at == 0.3 && !r->rewind, "a step cut before: ends where it was cut");
  AF_CHECK(!AFI::Noise_level(setup(s)).after_step(p.get()), "no noise criterion: no stop");
  const auto before = AFI::Noise_level::before_first_step(2, 1);
  AF_CHECK(before && *before == 0.5, "the input's limit surface twice the noise off: halfway to it");
  AF_CHECK(!AFI::Noise_level::before_first_step(0.9, 1), "the limit surface within the noise: the run goes on");
  AFI::Step_controller control;
  double fraction = -1;
  AF_CHECK(AFI::Noise_level::judge_candidate(control, 0.5, 1.01, 1, fraction) == AFI::Noise_level::Candidate::CUT &&
           std::abs(fraction - 0.5 / 0.51) < 1e-15, "within the tolerance of the target: cut on the secant");
  AF_CHECK(AFI::Noise_level::judge_candidate(control, 0.5, 2, 1, fraction) == AFI::Noise_level::Candidate::RETAKE &&
           std::abs(control.factor() - 1.0 / 3) < 1e-15, "far past it: retaken with the secant's fraction");
}

void levelling_off()
{
  AFI::Stepper_settings s;
  s.order = 4;
  Progress p;
  p.step.time_step = 16e-4;   // h = 0.5: the threshold time_step / (16 h^4) = 1.6e-3
  p.before = 1; p.discrepancy = 1.001;   // growth 0.999e-3
  auto r = AFI::Noise_removed(setup(s, true)).after_step(p.get());
  AF_CHECK(r && r->reason == AF::Stop_reason::NOISE_REMOVED, "fourth order: growth below the decay of a 4 pi h wave");
  p.discrepancy = 1.002;   // growth 1.996e-3
  AF_CHECK(!AFI::Noise_removed(setup(s, true)).after_step(p.get()), "fourth order: growth above it");
  s.strength = 2;   // h read as 1: threshold 1e-4
  p.discrepancy = 1.001;
  AF_CHECK(!AFI::Noise_removed(setup(s, true)).after_step(p.get()), "strength 2: waves twice as long");
  s.strength = 1;
  s.order = 2;
  AF_CHECK(!AFI::Noise_removed(setup(s, true)).after_step(p.get()), "second order: never");
  p.discrepancy = 1.009;
  r = AFI::Held_by_bound(setup(s, true, true)).after_step(p.get());
  AF_CHECK(r && r->reason == AF::Stop_reason::DEVIATION_BOUND, "under a bound: growth below 1%");
  AF_CHECK(!AFI::Held_by_bound(setup(s, true, false)).after_step(p.get()), "without a bound: never");
  p.discrepancy = 1.02;
  AF_CHECK(!AFI::Held_by_bound(setup(s, true, true)).after_step(p.get()), "under a bound: growth of 2% goes on");
}

void cramped_flow()
{
  AFI::Stepper_settings s;
  Progress p;
  const AFI::Cramped_flow rule(setup(s));
  p.control.reject(5); p.control.reject(5);   // 1/16
  for(int k = 1; k <= 4; ++k)
  {
    p.control.accept();
    p.step.step = std::size_t(k + 6);
    const auto r = rule.after_step(p.get());
    AF_CHECK(bool(r) == (k == 4), "cramped after the fourth sliver in a row, not before (" + std::to_string(k) + ")");
    if(r) AF_CHECK(r->reason == AF::Stop_reason::STEP_REJECTED && r->message.find("steps 7 to 10") == 0 &&
                   r->message.find("1/16") != std::string::npos && r->message.find("folded otherwise") != std::string::npos,
                   "the message names the steps, the sliver and why: " + r->message);
  }
}

// answers `reason` when `on`, and counts how often it was asked
struct Probe_rule
{
  static int asked;
  bool on;
  explicit Probe_rule(const AFI::Stop_rule_setup& s) : on(s.bound_active) {}
  std::optional<AFI::Stop> after_step(const AFI::Step_progress&) { ++asked; return on ? std::optional<AFI::Stop>(AFI::Stop{ AF::Stop_reason::CALLBACK }) : std::nullopt; }
};
int Probe_rule::asked = 0;

void order_and_folds()
{
  AFI::Stepper_settings s;
  s.stopping = AF::Stopping_criteria::none();
  s.stopping.steady_speed = 1;
  Progress p;
  p.moved_relative = 0.5;
  AFI::Ordered_stop_rules<AFI::Steady_state, Probe_rule> steady_first(setup(s, false, true));
  auto r = steady_first.after_step(p.get());
  AF_CHECK(r && r->reason == AF::Stop_reason::STEADY_STATE && Probe_rule::asked == 0, "the first rule wins, the next is not asked");
  AFI::Ordered_stop_rules<Probe_rule, AFI::Steady_state> probe_first(setup(s, false, true));
  r = probe_first.after_step(p.get());
  AF_CHECK(r && r->reason == AF::Stop_reason::CALLBACK && Probe_rule::asked == 1, "in the list's order");
  AFI::Ordered_stop_rules<Probe_rule, AFI::Steady_state> silent(setup(s, false, false));
  p.moved_relative = 2;
  AF_CHECK(!silent.after_step(p.get()) && Probe_rule::asked == 2, "every rule asked when none answers");

  AF_CHECK(!AFI::new_folds(3, 3, 0), "as many folds as the input: kept");
  const auto back = AFI::new_folds(5, 3, 7);
  AF_CHECK(back && !back->fails && back->message.find("(step 7)") != std::string::npos, "more folds: back to step 7");
  const auto none = AFI::new_folds(5, 3, 0);
  AF_CHECK(none && none->fails, "more folds from the first step on: failed");
}

} // namespace

int main()
{
  paper_criteria();
  steady_state();
  noise_level();
  levelling_off();
  cramped_flow();
  order_and_folds();
  return AF_test::report();
}
