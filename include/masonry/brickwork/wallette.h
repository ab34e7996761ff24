/**
 * @file
 * The mesoscale wallette model: mesh of enlarged bricks, joints found as
 * coincident face pairs, Newton solution under a displacement-controlled
 * platen. The parts of the model live in source/brickwork/model/ (private
 * headers), the outputs in source/brickwork/postprocess/; this header only
 * carries the settings, one struct per concern.
 */
#ifndef masonry_brickwork_wallette_h
#define masonry_brickwork_wallette_h

#include <masonry/brickwork/bond.h>
#include <masonry/core/run_context.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    class BrickMaterial;
    class InterfaceLaw;
    namespace postprocess
    {
      class Postprocessor;
    }

    /** The mesh of enlarged bricks (`Elements along ...', `Joints',
     * `Mesh distortion'). */
    struct MeshSettings
    {
      /** Sizes of the enlarged brick and of the wallette. */
      WalletteSize size;
      /** Elements along the enlarged brick's length, width and height: the
       * mesh spacing is length/n_l, width/n_w, height/n_h everywhere. */
      unsigned int n_l = 4, n_w = 2, n_h = 2;
      /**
       * Merge the coincident vertices of neighbouring bricks (a perfectly
       * bonded continuum without interfaces, as a reference).
       */
      bool bonded = false;
      /**
       * Amplitude of a smooth distortion of the mesh, as a fraction of the
       * mesh spacing in each direction (dimensionless, 0 to 0.2; 0: the
       * regular mesh). With interfaces, each brick's vertices move by a
       * bubble that vanishes on the brick's faces (joint faces and the
       * wallette's faces stay as they are); with `bonded' joints, one
       * global map moves every vertex but keeps each face of the wallette
       * in its plane. For patch tests: the exact solution of uniform
       * compression does not change.
       */
      double distortion = 0;
      /** Gauss (true) or Lobatto (false) points on interfaces. */
      bool gauss = false;
      /**
       * Mesh each unit as two halves that meet at a vertical plane through
       * its middle, normal to its longer horizontal side (in line with the
       * head joints of the next course for a stretcher): the halves do not
       * share vertices, so the plane becomes a splitting interface. Units
       * whose half is not a whole number of cells stay whole.
       */
      bool split_units = false;
      /**
       * The `detailed' model (`Model = detailed'): the units at their actual
       * size (the enlarged box less mortar_thickness along its upper faces in
       * x, y and z), the mortar between them meshed as one layer of
       * hexahedra of thickness mortar_thickness with its own material, and
       * zero-thickness interfaces (the bond) between units and mortar.
       * false: the `simplified' model of enlarged bricks.
       */
      bool detailed = false;
      /** Thickness of the mortar joints of the detailed model, m. */
      double mortar_thickness = 0;
      /**
       * Filled fraction of the height of every head joint and of every
       * collar joint (detailed model; `Head joint fill', `Collar joint
       * fill'), 0 to 1: each vertical joint is mortar from the bed joint
       * below up to this fraction of the course height, the rest up to the
       * bed joint above is a void (no cells; the unit faces there are
       * free). Where a head joint meets the collar joint the column counts
       * as collar joint. 1: full joints.
       */
      double head_joint_fill = 1, collar_joint_fill = 1;
      /**
       * Width of the unfilled strip of every bed joint on each side of a
       * collar joint (detailed model; `Collar bed gap'), m: the bed-joint
       * mortar under and over the collar plane, widened by this on both
       * sides, is a void (the beds of the wythes spread separately and not
       * joined). 0: full bed joints.
       */
      double collar_bed_gap = 0;
    };

    /** The platens and the gauge (`Platen ...', `Gauge length'). */
    struct PlatenSettings
    {
      /** Platens hold the wall faces laterally (true) or let them slide. */
      bool lateral_fixed = false;
      /** Unit direction of the top platen's motion. */
      std::array<double, 3> direction = {{0, 0, -1}};
      /**
       * Length of a virtual LVDT on the front face (y = 0) at mid-length,
       * centred at mid-height (m); 0: no gauge.
       */
      double gauge_length = 0;
    };

    /** The loading protocol and the step size (`Protocol', `Number of
     * steps', `Cycle amplitudes', ...). */
    struct ProtocolSettings
    {
      /** Final platen displacement (m, along direction). */
      double target_displacement = 0;
      /** Nominal number of steps (the largest step is target / n_steps). */
      unsigned int n_steps = 50;
      /** Consecutive halvings of a step before the run stops. */
      unsigned int max_cutbacks = 10;
      /** Factor on the step after an easy step (up to the nominal step). */
      double growth = 2;
      /** Platen displacements (m, along direction) at which the cycles
       * turn back; empty: one monotonic ramp to target_displacement. */
      std::vector<double> cycle_amplitudes;
      /** Cycles at each amplitude (repeats give the common and stability
       * points). */
      unsigned int cycles_per_amplitude = 1;
      /** Unloading of a cycle ends when the stress has dropped to this
       * (Pa, along the platen direction). */
      double unloading_stress = 0.1e6;
      /** The run ends (status completed, with a message) once the specimen
       * has collapsed: on a loading leg the stress has fallen below this
       * fraction of the peak (model::collapse_problem()); 0: never. */
      double collapse_ratio = 0;
      /** Platen speed (m/s): the pseudo-time of a step is its platen
       * displacement increment divided by this (viscous regularisation). */
      double platen_speed = 1e-5;
      /** Stop (status `interrupted', checkpoint written) after this many
       * converged steps of this run (0: no limit). */
      unsigned int max_steps = 0;
    };

    /** Newton-Raphson (`Maximum Newton iterations', `Newton tolerance',
     * `Line search'). */
    struct NewtonSettings
    {
      /** Iterations and relative residual tolerance. */
      unsigned int max_newton       = 20;
      double       newton_tolerance = 1e-8;
      bool         line_search      = true;
      /** First iterate of a step: the last converged solution plus the
       * last step's displacement increment scaled to this step
       * (`Predictor' = extrapolated), or the last converged solution with
       * only the platen moved (constant). */
      bool extrapolated_predictor = false;
      /** The residual is measured against the largest of the platen
       * reactions of the iterate and of every converged step so far
       * (`Residual reference' = largest reaction), not against the
       * present reactions only (present reaction). */
      bool largest_reaction_reference = false;
      /** A full Newton correction that left at most this fraction of the
       * residual is followed by chord corrections with the same LU
       * factorisation while each leaves at most this fraction (`Newton
       * chord contraction'; 0: none). */
      double chord_contraction = 0.1;
    };

    /** The linear solver (`Linear solver', `Linear solver tolerance'). */
    struct LinearSolverSettings
    {
      /** "direct", "direct klu", "cg amg" or "gmres amg". */
      std::string linear_solver = "direct";
      /** Relative tolerance of the iterative solvers. */
      double linear_tolerance = 1e-10;
      /** `direct': GMRES iterations with the last LU factorisation as
       * the preconditioner before the matrix is factorised anew (0: every
       * solve factorises; `Factorisation reuse iterations'). */
      unsigned int reuse_iterations = 0;
    };

    /** Integration of the laws (`Damage integration', `IMPL-EX ...'). */
    struct IntegratorSettings
    {
      /** IMPL-EX integration of brick and joint damage: internal
       * variables extrapolated in each step, updated after it. */
      bool implex = false;
      /** IMPL-EX step control: largest allowed difference between the
       * extrapolated and the updated damage in a step. */
      double implex_tolerance = 0.05;
      /** IMPL-EX step control never shrinks the step below this fraction
       * of the nominal step (a softening snap keeps the damage error large
       * however small the step). */
      double implex_minimum_step = 0.01;
      /** The floor of the unloading legs, as a fraction of the nominal
       * step (`IMPL-EX minimum step when unloading'; 0: the same as
       * implex_minimum_step). */
      double implex_minimum_step_unloading = 0;
      /** IMPL-EX: a step at the floor whose damage error is over the
       * tolerance is solved again with its own updated states, frozen,
       * until their update no longer changes them (else it is accepted). */
      bool implex_floor_correction = false;
      /** IMPL-EX (`IMPL-EX floor correction = iterate at any step'): a step
       * of any size over the tolerance is corrected at its own size first;
       * only a correction that does not reach the tolerance within
       * model::max_passes_above_floor (4) passes, or fails, is redone
       * smaller. */
      bool implex_correct_any_step = false;
      /** Threads per MPI rank that evaluate the laws of the cells and
       * interfaces in an assembly (`Assembly threads'; 0: deal.II's
       * default, the cores divided among the ranks). */
      unsigned int threads = 1;
    };

    /** Element deletion and strength scatter (`Deletion strain', `Maximum
     * deletions per step', `Strength scatter', `Random seed'). */
    struct SpecimenSettings
    {
      /** Remove cells whose maximum principal strain exceeds
       * deletion_strain after a converged step (0: never). */
      double deletion_strain = 0;
      /** Past deletion_strain a cell fades out: its stress and stiffness
       * are scaled by 1 - (e1 - deletion_strain) l / deletion_fade_opening
       * (l: its crack-band length, BrickPoint::characteristic_length, e1: the
       * largest cell-averaged principal strain so far), and it is deleted when
       * the factor reaches 0, m (0: deleted at once). */
      double deletion_fade_opening = 0;
      /** Past deletion_strain a cell also fades with its shortening since
       * then: the factor is at most 1 - (s - s_split) l /
       * deletion_crushing_length (s: largest compressive principal strain
       * of the cell), m (0: no crushing fade). */
      double deletion_crushing_length = 0;
      /** A cell past deletion_strain (or at the end of its fade) is
       * deleted only when the largest absolute principal value of its
       * cell-averaged stress is at most this, Pa: a cell that still
       * carries load stays (0: no such condition). */
      double deletion_stress = 0;
      /** At most this many cells are deleted after one step. */
      unsigned int max_deletions = 10;
      /** Coefficient of variation of the strengths of bricks and joints
       * (a normal factor per brick and per joint, cut at 0.2 and 1.8). */
      double strength_scatter = 0;
      /** Seed of the random strength factors. */
      unsigned int seed = 1;
    };

    /** Output files (`Output interval', `Write VTU', `Output format',
     * `Write plot', `Write CalculiX input'). */
    struct OutputSettings
    {
      /** Write VTU every this many converged steps (0: only the last). */
      unsigned int vtu_interval = 10;
      /** Write VTU/PVD at all. */
      bool write_vtu = true;
      /** Brick fields as HDF5 + XDMF (solution.xdmf, solution_NNNN.h5)
       * instead of VTU/PVTU + PVD. */
      bool hdf5 = false;
      /** Render curve.png with matplotlib. */
      bool write_plot = true;
      /**
       * Write the mesh and the final platen displacement as a CalculiX
       * input (calculix.inp) and the computed nodal displacements
       * (nodal_displacements.csv) in the same numbering.
       */
      bool write_calculix = false;
    };

    /** Checkpoints (`Checkpoint interval', `Resume'). */
    struct CheckpointSettings
    {
      /** Write a checkpoint every this many converged steps (0: only when
       * the run stops early). */
      unsigned int checkpoint_interval = 0;
      /** Continue from the checkpoint in the output directory. */
      bool resume = false;
    };

    /** Everything the wallette model needs besides its plugins: one
     * struct per concern, each part of the model gets only its own. */
    struct WalletteSettings
    {
      MeshSettings         mesh;
      PlatenSettings       platen;
      ProtocolSettings     protocol;
      NewtonSettings       newton;
      LinearSolverSettings linear_solver;
      IntegratorSettings   integrator;
      SpecimenSettings     specimen;
      OutputSettings       output;
      CheckpointSettings   checkpoint;
    };

    /** Mesh spacing in x, y, z (m). */
    std::array<double, 3>
    mesh_spacing(const MeshSettings &settings);

    /**
     * Check that every box is a whole number of mesh cells in each
     * direction; throws an ExcParameter naming the entry to change.
     */
    void
    check_mesh(const std::vector<Box> &boxes, const MeshSettings &settings);

    /**
     * Build, solve and write the results of a wallette under a platen; the
     * @p postprocessors write the outputs, in their order. With
     * MeshSettings::split_units the splitting interfaces through the units
     * follow @p splitting_law (required then); with MeshSettings::detailed
     * the mortar cells follow @p mortar_material (required then).
     */
    void
    run_wallette(
      const std::vector<Box>                                   &boxes,
      const BrickMaterial                                      &material,
      const InterfaceLaw                                       &law,
      const WalletteSettings                                   &settings,
      std::vector<std::unique_ptr<postprocess::Postprocessor>> &postprocessors,
      RunContext                                               &context,
      const InterfaceLaw  *splitting_law   = nullptr,
      const BrickMaterial *mortar_material = nullptr);
  } // namespace brickwork
} // namespace masonry

#endif
