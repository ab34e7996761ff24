/**
 * The loading protocols and the step controller on their own. The cyclic
 * protocol's legs turn at the given amplitudes, each repeated `Cycles per
 * amplitude' times, with the cycles numbered from 1; the monotonic one is
 * one ramp. Driven through the step controller against a linear specimen
 * (stress = k x displacement), the platen reaches each amplitude exactly
 * (the turning points), never passes it, and each unloading stops where the
 * stress is the unloading stress, the last step aimed with the slope of
 * the previous one (exact for a linear response). The IMPL-EX step control
 * redoes a step over the tolerance smaller, down to the floor of its leg,
 * where it is accepted; an unloading leg that inherits the loading floor
 * starts at its own.
 */
#include <masonry/brickwork/protocol.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <array>
#include <cmath>
#include <iostream>

#include "../source/brickwork/solution/step_controller.h"
#include "vault_tests.h"

using namespace masonry::brickwork;
using namespace masonry::brickwork::model;
using Protocols = masonry::plugins::Registry<Protocol>;

namespace
{
  /** The protocol @p name with the Wallette entries @p entries, for a
   * wallette 1 m high. */
  std::unique_ptr<Protocol>
  make(const std::string &name, const std::string &entries)
  {
    dealii::ParameterHandler prm;
    Protocols::declare_parameters(prm);
    prm.parse_input_from_string("subsection Wallette\nset Protocol = " + name +
                                "\n" + entries + "end\n");
    auto protocol = Protocols::create(prm);
    protocol->initialize(1.);
    return protocol;
  }

  /** A converged step of @p outcome: the controller's decision. */
  Decision
  solved(StepController &c, const Step &step, const double error)
  {
    StepOutcome outcome;
    outcome.converged    = true;
    outcome.iterations   = 3;
    outcome.damage_error = error;
    return c.solved(step, outcome);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::ConditionalOStream               quiet(std::cout, false);
  const std::vector<double>                amplitudes = {1e-3, 2.5e-3, 4e-3};
  const double                             unloading  = 0.3e6;
  const auto                               cyclic =
    make("cyclic",
         "set Cycle amplitudes = 1e-3, 2.5e-3, 4e-3\n"
         "set Cycles per amplitude = 2\nset Target strain = 4e-3\n"
         "set Unloading stress = 0.3e6\n");
  const std::vector<Leg> legs = cyclic->legs();
  bool                   ok   = legs.size() == 12 && cyclic->is_cyclic() &&
            cyclic->cycles_per_amplitude() == 2 &&
            cyclic->target_displacement() == 4e-3;
  for (unsigned int i = 0; ok && i < legs.size(); ++i)
    ok = legs[i].cycle == i / 2 + 1 && legs[i].unloading == (i % 2 == 1) &&
         legs[i].target == (i % 2 == 1 ? 0. : amplitudes[i / 4]) &&
         cyclic->amplitude(i / 2 + 1) == amplitudes[i / 4];
  vault_tests::check(ok,
                     "cyclic: 3 amplitudes x 2 cycles = 12 legs, load to "
                     "the amplitude, unload towards 0, cycles 1 to 6");

  // a linear specimen: stress = k displacement (Pa, m); 7 nominal steps
  StepSettings steps;
  steps.n_steps             = 7;
  const double            k = 5e9;
  std::vector<CurvePoint> curve(1);
  std::vector<double>     turning, ends;
  {
    StepController controller(*cyclic, steps, false, 20, {{0., 1e30}}, quiet);
    Step           step;
    while (controller.next(curve, step) && curve.size() < 100000)
      {
        controller.accept(step, 0);
        CurvePoint p;
        p.displacement = step.to;
        p.stress       = k * step.to;
        p.cycle        = step.leg.cycle;
        p.unloading    = step.leg.unloading;
        curve.push_back(p);
        if (!step.leg.unloading && step.to == step.leg.target)
          turning.push_back(step.to);
      }
  }
  // the end of every unloading: the last unloading point of each cycle
  for (unsigned int i = 1; i < curve.size(); ++i)
    if (curve[i].unloading &&
        (i + 1 == curve.size() || !curve[i + 1].unloading))
      ends.push_back(curve[i].stress);
  double max_over = 0;
  for (const auto &p : curve)
    if (p.cycle > 0)
      max_over =
        std::max(max_over, p.displacement - cyclic->amplitude(p.cycle));
  ok = turning.size() == 6;
  for (unsigned int c = 0; ok && c < 6; ++c)
    ok = turning[c] == amplitudes[c / 2];
  vault_tests::check(ok && max_over <= 0,
                     "cyclic: the platen turns exactly at each amplitude and "
                     "never passes it");
  bool ends_ok = ends.size() == 6;
  for (const double e : ends)
    ends_ok = ends_ok && std::abs(e - unloading) < 1e-6 * unloading;
  vault_tests::check(ends_ok,
                     "cyclic: every unloading ends at the unloading stress "
                     "(1e-6)");

  const auto mono = make("monotonic", "set Target strain = 3e-3\n");
  vault_tests::check(mono->legs().size() == 1 && !mono->legs()[0].unloading &&
                       mono->legs()[0].target == 3e-3 &&
                       mono->amplitude(1) == 3e-3 && !mono->is_cyclic(),
                     "monotonic: one ramp to the target");

  // IMPL-EX step control (`IMPL-EX floor correction = accept'): a step
  // over the tolerance is redone smaller in proportion (0.9 / ratio, to no
  // less than a fifth), never below the floor of its leg, and at that floor
  // it is accepted; the unloading legs take `IMPL-EX minimum step when
  // unloading' x the nominal step as theirs (0: the loading floor). One
  // cycle to 1e-3 m in 10 nominal steps of 1e-4 m.
  const auto one_cycle                = make("cyclic",
                              "set Cycle amplitudes = 1e-3\n"
                                             "set Target strain = 1e-3\n");
  steps.n_steps                       = 10;
  steps.implex_tolerance              = 0.05;
  steps.implex_minimum_step           = 0.1;
  steps.implex_minimum_step_unloading = 0.5;
  const double d_nominal              = 1e-4;
  // the first accepted step of each leg when every step is 4 x over the
  // tolerance (a snap): redone smaller, then accepted at the floor
  const auto floors_of = [&](const StepSettings &s) {
    StepController          c(*one_cycle, s, true, 20, {{0., 1e30}}, quiet);
    std::vector<CurvePoint> path(1);
    std::array<double, 2>   first{{0, 0}};
    std::array<bool, 2>     seen{{false, false}};
    Step                    step;
    while (c.next(path, step) && path.size() < 1000)
      {
        if (solved(c, step, 4 * s.implex_tolerance).kind !=
            Decision::Kind::accept)
          continue;
        if (!seen[step.leg.unloading])
          first[step.leg.unloading] = step.size;
        seen[step.leg.unloading] = true;
        c.accept(step, 0);
        CurvePoint p;
        p.displacement = step.to;
        p.stress       = 1e9 * step.to;
        p.cycle        = step.leg.cycle;
        p.unloading    = step.leg.unloading;
        path.push_back(p);
        c.grow(3);
      }
    return first;
  };
  const auto both = floors_of(steps);
  vault_tests::check(std::abs(both[0] - 0.1 * d_nominal) < 1e-12 * d_nominal &&
                       std::abs(both[1] - 0.5 * d_nominal) < 1e-12 * d_nominal,
                     "IMPL-EX: a step 4 x over the tolerance is accepted at "
                     "0.1 x the nominal step when loading and at 0.5 x when "
                     "unloading; the unloading leg starts at its own floor "
                     "when the loading leg hands on 0.1 x");
  steps.implex_minimum_step_unloading = 0;
  const auto same                     = floors_of(steps);
  vault_tests::check(std::abs(same[1] - 0.1 * d_nominal) < 1e-12 * d_nominal,
                     "IMPL-EX: with `IMPL-EX minimum step when unloading' = "
                     "0 the unloading legs keep the loading floor");
}
