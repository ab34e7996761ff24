/**
 * The loading protocols on their own (issue 15). The cyclic protocol's legs
 * turn at the given amplitudes, each repeated `Cycles per amplitude' times,
 * with the cycles numbered from 1; the monotonic one is one ramp. Driven
 * through next_position() against a linear specimen (stress = k x
 * displacement), the platen reaches each amplitude exactly (the turning
 * points), never passes it, and each unloading stops where the stress is the
 * unloading stress, the last step aimed with the slope of the previous one
 * (exact for a linear response).
 */
#include <deal.II/base/mpi.h>

#include <array>
#include <cmath>
#include <iostream>

#include "../source/brickwork/model/step_control.h"
#include "vault_tests.h"

using namespace masonry::brickwork;
using namespace masonry::brickwork::model;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ProtocolSettings                         s;
  s.cycle_amplitudes                = {1e-3, 2.5e-3, 4e-3};
  s.cycles_per_amplitude            = 2;
  s.target_displacement             = 4e-3;
  s.n_steps                         = 7;
  s.unloading_stress                = 0.3e6;
  const auto                 cyclic = create_protocol(s);
  const std::vector<Segment> legs   = cyclic->legs();
  bool                       ok     = legs.size() == 12;
  for (unsigned int i = 0; ok && i < legs.size(); ++i)
    ok = legs[i].cycle == i / 2 + 1 && legs[i].unloading == (i % 2 == 1) &&
         legs[i].target == (i % 2 == 1 ? 0. : s.cycle_amplitudes[i / 4]) &&
         cyclic->amplitude(i / 2 + 1) == s.cycle_amplitudes[i / 4];
  vault_tests::check(ok,
                     "cyclic: 3 amplitudes x 2 cycles = 12 legs, load to "
                     "the amplitude, unload towards 0, cycles 1 to 6");

  // a linear specimen: stress = k displacement (Pa, m)
  const double            k       = 5e9;
  const double            nominal = s.target_displacement / s.n_steps;
  std::vector<CurvePoint> curve(1);
  Progress                progress;
  progress.increment = nominal;
  std::vector<double> turning, ends;
  while (progress.segment < legs.size())
    {
      const Segment &leg = legs[progress.segment];
      double         next;
      if (!next_position(leg, curve, s, nominal, progress, next))
        continue;
      progress.applied = next;
      CurvePoint p;
      p.displacement = next;
      p.stress       = k * next;
      p.cycle        = leg.cycle;
      p.unloading    = leg.unloading;
      curve.push_back(p);
      if (!leg.unloading && next == leg.target)
        turning.push_back(next);
      if (curve.size() > 100000)
        break;
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
    ok = turning[c] == s.cycle_amplitudes[c / 2];
  vault_tests::check(ok && max_over <= 0,
                     "cyclic: the platen turns exactly at each amplitude and "
                     "never passes it");
  bool ends_ok = ends.size() == 6;
  for (const double e : ends)
    ends_ok =
      ends_ok && std::abs(e - s.unloading_stress) < 1e-6 * s.unloading_stress;
  vault_tests::check(ends_ok,
                     "cyclic: every unloading ends at the unloading stress "
                     "(1e-6)");

  ProtocolSettings m;
  m.target_displacement = 3e-3;
  const auto mono       = create_protocol(m);
  vault_tests::check(mono->legs().size() == 1 && !mono->legs()[0].unloading &&
                       mono->legs()[0].target == 3e-3 &&
                       mono->amplitude(1) == 3e-3,
                     "monotonic: one ramp to the target");

  // IMPL-EX step control (`Damage integration = implex', `accept'): a step
  // over the tolerance is redone smaller in proportion (0.9 / ratio, to no
  // less than a fifth), never below the floor of its leg, and at that floor
  // it is accepted; the unloading legs take `IMPL-EX minimum step when
  // unloading' x the nominal step as theirs (0: the loading floor)
  const double       d_nominal = 1e-4;
  IntegratorSettings integrator;
  integrator.implex                        = true;
  integrator.implex_tolerance              = 0.05;
  integrator.implex_minimum_step           = 0.1;
  integrator.implex_minimum_step_unloading = 0.5;
  ProtocolSettings p;
  p.growth             = 2;
  const auto floors_of = [&](const IntegratorSettings &i) {
    // the step a run at the nominal size ends at when every step is 4 x
    // over the tolerance (a snap): redone smaller, then accepted at the floor
    const auto control =
      create_step_size_control(i, p, NewtonSettings(), d_nominal);
    std::array<double, 2> floors{};
    for (const bool unloading : {false, true})
      {
        control->set_leg({0., unloading, 1});
        Progress progress;
        progress.increment = d_nominal;
        for (unsigned int k = 0; k < 20; ++k)
          {
            const double taken = progress.increment;
            if (control->judge(taken, 4 * i.implex_tolerance, progress) ==
                Verdict::accept)
              {
                control->after_step(3, progress);
                floors[unloading] = taken;
                break;
              }
          }
      }
    return floors;
  };
  const auto both = floors_of(integrator);
  vault_tests::check(std::abs(both[0] - 0.1 * d_nominal) < 1e-12 * d_nominal &&
                       std::abs(both[1] - 0.5 * d_nominal) < 1e-12 * d_nominal,
                     "IMPL-EX: a step 4 x over the tolerance is accepted at "
                     "0.1 x the nominal step when loading and at 0.5 x when "
                     "unloading");
  {
    // an unloading leg that inherits the loading floor starts at its own
    const auto control =
      create_step_size_control(integrator, p, NewtonSettings(), d_nominal);
    Progress progress;
    progress.increment = 0.1 * d_nominal;
    control->start_leg({0., true, 1}, progress);
    const double unloading = progress.increment;
    control->start_leg({1e-3, false, 2}, progress);
    vault_tests::check(std::abs(unloading - 0.5 * d_nominal) <
                           1e-12 * d_nominal &&
                         progress.increment == unloading,
                       "IMPL-EX: an unloading leg starts at its floor (0.5 "
                       "x the nominal step) when the loading leg hands on "
                       "0.1 x; a loading leg keeps the step it is given");
  }
  integrator.implex_minimum_step_unloading = 0;
  const auto same                          = floors_of(integrator);
  vault_tests::check(std::abs(same[1] - 0.1 * d_nominal) < 1e-12 * d_nominal,
                     "IMPL-EX: with `IMPL-EX minimum step when unloading' = "
                     "0 the unloading legs keep the loading floor");
}
