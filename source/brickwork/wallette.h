/**
 * @file
 * The inputs and the run of the wallette model: the settings of every part
 * of the model (each struct declares and reads its own entries of
 * `subsection Wallette', next to the part it sets) and run_wallette(),
 * which builds the parts and moves the platen through the protocol.
 * Private to the library: the analysis `wallette'
 * (source/analysis/wallette_compression.cc) reads the file and calls it.
 */
#ifndef masonry_brickwork_wallette_h
#define masonry_brickwork_wallette_h

#include <masonry/brickwork/bond.h>
#include <masonry/brickwork/law_set.h>
#include <masonry/brickwork/linear_solver.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/brickwork/protocol.h>
#include <masonry/core/run_context.h>

#include <memory>
#include <vector>

#include "assembly/assembler.h"
#include "assembly/integrator.h"
#include "assembly/system.h"
#include "checkpoint.h"
#include "solution/deletion.h"
#include "solution/newton.h"
#include "solution/step_controller.h"
#include "specimen/mesh.h"
#include "specimen/specimen.h"

namespace masonry
{
  namespace brickwork
  {
    class BrickMaterial;
    class InterfaceLaw;

    /** Everything the wallette model needs besides its plugins: one
     * struct per concern, each part of the model gets only its own. */
    struct WalletteSettings
    {
      MeshSettings              mesh;
      model::PlatenSettings     platen;
      model::StepSettings       steps;
      model::NewtonSettings     newton;
      model::AssemblySettings   assembly;
      model::SpecimenSettings   specimen;
      model::DeletionSettings   deletion;
      OutputSettings            output;
      model::CheckpointSettings checkpoint;

      /** Every part's entries, in the present subsection. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /** Every part reads its entries; errors name the entry. */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /** The plugins of a run, created from the parameter file. */
    struct WallettePlugins
    {
      Protocol          &protocol;
      model::Integrator &integrator;
      LinearSolver      &solver;
      /** The outputs, in their order. */
      std::vector<std::unique_ptr<postprocess::Postprocessor>> &postprocessors;
    };

    /**
     * Whether @p laws suit the run: under an integrator that extrapolates
     * the laws (IMPL-EX) every nonlinear law extrapolates, and only the
     * units' law has a nonlocal length (which needs IMPL-EX without its
     * floor correction); else an error naming the entry.
     */
    void
    check_laws(const LawSet            &laws,
               const model::Integrator &integrator,
               const WalletteSettings  &settings);

    /**
     * Build, solve and write the results of a wallette under a platen, with
     * the @p laws of its cell regions (the units; with
     * MeshSettings::detailed also the mortar) and joint types (bed, head
     * and collar; with MeshSettings::split_units also the splitting
     * interfaces through the units).
     */
    void
    run_wallette(const std::vector<Box> &boxes,
                 const LawSet           &laws,
                 const WalletteSettings &settings,
                 const WallettePlugins  &plugins,
                 RunContext             &context);
  } // namespace brickwork
} // namespace masonry

#endif
