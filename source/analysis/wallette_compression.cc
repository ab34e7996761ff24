/**
 * @file
 * The wallette analysis: a mesoscale model of bonded brickwork between two
 * rigid platens, displacement controlled (monotonic protocol).
 */
#include <masonry/analysis/interface.h>
#include <masonry/brickwork/bond.h>
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/brickwork/wallette.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

#include "../brickwork/laws/splitting.h"
#include "wallette_solver_entries.h"

namespace masonry
{
  namespace analysis
  {
    namespace
    {
      /** The mortar of the detailed model: a brick material of its own. */
      const char *const mortar_section = "Mortar material";

      void
      declare_mortar_material(dealii::ParameterHandler &prm)
      {
        using Materials = plugins::Registry<brickwork::BrickMaterial>;
        Materials::declare_parameters(prm, mortar_section);
        // the family's entry, declared again with the mortar's own default
        // and text (the family's text is about the enlarged bricks)
        prm.enter_subsection(mortar_section);
        const bool has_mortar =
          std::any_of(Materials::entries().begin(),
                      Materials::entries().end(),
                      [](const auto &e) { return e.name == "mortar"; });
        prm.declare_entry(
          "Model",
          has_mortar ? "mortar" : Materials::entries().front().name,
          dealii::Patterns::Selection(Materials::pattern()),
          Materials::documentation(
            "The constitutive law of the mortar cells of the `detailed' "
            "model (`subsection Wallette/Model = detailed'), any brick "
            "material; not used by the `simplified' model, whose enlarged "
            "bricks contain the mortar."));
        prm.leave_subsection();
      }

      [[maybe_unused]] const bool mortar_declared =
        (plugins::add_subsystem(
           {mortar_section, "Model", &declare_mortar_material}),
         true);
    } // namespace

    /**
     * A wallette of enlarged bricks joined by zero-thickness cohesive
     * interfaces, loaded by a top platen moving by a prescribed
     * displacement; the bottom platen is fixed.
     */
    class WalletteCompression : public Interface
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Double;
        using dealii::Patterns::Integer;
        using dealii::Patterns::Selection;
        prm.declare_entry("Brick length",
                          "0.215",
                          Double(0),
                          "Length of a brick without mortar, m (>= 1e-6).");
        prm.declare_entry("Brick width",
                          "0.1025",
                          Double(0),
                          "Width of a brick without mortar, m (>= 1e-6).");
        prm.declare_entry("Brick height",
                          "0.065",
                          Double(0),
                          "Height of a brick without mortar, m (>= 1e-6).");
        prm.declare_entry("Joint thickness",
                          "0.010",
                          Double(0),
                          "Thickness of the mortar joints, m (>= 0): each "
                          "enlarged brick is the brick plus half a joint on "
                          "every side. `Model = simplified': the joints "
                          "become zero-thickness interfaces; `detailed': the "
                          "mortar is meshed as one layer of hexahedra of "
                          "this thickness (>= 1e-6 then).");
        prm.declare_entry(
          "Model",
          "simplified",
          Selection("simplified|detailed"),
          "`simplified': enlarged bricks (brick plus half a joint all "
          "round) joined by zero-thickness interfaces that stand for the "
          "mortar (`Interface law', whose penalties then represent the "
          "mortar's stiffness, e.g. Lourenco-Rots from E_b, E_m, nu and "
          "the joint thickness). `detailed': the units at their actual "
          "size (`Brick length/width/height'), the mortar of bed and head "
          "joints (and collar joints) meshed as one layer of hexahedra "
          "`Joint thickness' thick with `subsection Mortar material' (any "
          "brick material), and the zero-thickness interfaces of the "
          "`Interface law' between units and mortar as the bond, whose "
          "penalties should then be stiff contact penalties (the mortar's "
          "compliance is in its cells); the wallette is one joint "
          "thickness shorter, thinner and lower than the enlarged one "
          "(outer faces are unit faces). Cells along the length, width "
          "and height of a unit are about its size / the enlarged mesh "
          "spacing; mortar layers are one cell thick. Not with `Mesh "
          "distortion'.");
        prm.declare_entry(
          "Collar bed gap",
          "0",
          Double(),
          "Width of the unfilled strip of every bed joint on each side of "
          "every collar joint, m (`Model = detailed' only, >= 0; the strips "
          "must stay apart and off the faces, e.g. g < 0.1025 m in a double "
          "and g < 0.05125 m in a triple english wall of 215 mm units): the "
          "bed-joint mortar in the plane of a collar joint, widened by this "
          "on both sides, is a void (no cells; the unit faces above and "
          "below it are free), as where the mortar beds of the wythes are "
          "spread separately and do not meet. A workmanship input, as a "
          "dismantled specimen shows it; no effect on a wall without collar "
          "joints. The plan area of the voids (`bed_void_area', m^2, summed "
          "over the bed joints) is in log.txt and summary.json.");
        for (const char *joint : {"Head", "Collar"})
          prm.declare_entry(
            std::string(joint) + " joint fill",
            "1",
            Double(),
            std::string("Filled fraction of the height of every ") +
              (joint[0] == 'H' ?
                 "head joint (perpend)" :
                 "collar joint (the vertical joint between the wythes of "
                 "the english bond; where a head joint meets it, the "
                 "column counts as collar joint)") +
              ", dimensionless, 0 to 1 (`Model = detailed' only): the "
              "joint is mortar from the bed joint below up to this "
              "fraction of the unit height, the rest, up to the bed joint "
              "above, is a void (no cells; the unit faces there are free). "
              "A workmanship input, as a survey or a dismantled specimen "
              "shows it. The areas of the joints and of their voids and "
              "the fill meshed (the grid line lies at the fraction "
              "exactly) are printed in log.txt and summary.json; 1: full "
              "joints.");
        prm.declare_entry("Courses",
                          "5",
                          Integer(1, 1000),
                          "Number of courses (rows of bricks) of the "
                          "wallette.");
        prm.declare_entry("Length in bricks",
                          "2",
                          Integer(1, 1000),
                          "Length of the wallette in (enlarged) brick "
                          "lengths.");
        prm.declare_entry("Elements along the length",
                          "4",
                          Integer(1, 64),
                          "Hexahedra along the length of an enlarged "
                          "stretcher; the mesh spacing (enlarged length / "
                          "this number) is used for every brick, so that the "
                          "meshes of neighbouring bricks match across the "
                          "joints (even for the stretcher bond, a multiple "
                          "of 4 for the english bond).");
        prm.declare_entry("Elements along the width",
                          "2",
                          Integer(1, 64),
                          "Hexahedra across the width of an enlarged "
                          "stretcher (mesh spacing across the wall).");
        prm.declare_entry("Elements along the height",
                          "2",
                          Integer(1, 64),
                          "Hexahedra over the height of an enlarged brick.");
        prm.declare_entry(
          "Platen lateral restraint",
          "fixed",
          Selection("fixed|free"),
          "`fixed': the platens hold the top and bottom faces in all "
          "directions (full friction); `free': they only act along z "
          "(frictionless; rigid motions in the plane are removed by "
          "pinning two points of the bottom face).");
        prm.declare_entry(
          "Platen direction",
          "0, 0, -1",
          dealii::Patterns::List(Double(), 3, 3),
          "Direction of the top platen's motion (x, y, z; normalised): "
          "`0, 0, -1' compresses the wallette, `0, 0, 1' pulls it, `1, 0, "
          "0' shears it (needs fixed platens). Stresses and strains are "
          "reported along this direction.");
        prm.declare_entry("Target strain",
                          "0.003",
                          Double(0),
                          "Final platen displacement divided by the height "
                          "of the wallette (dimensionless, > 0; the "
                          "displacement in m is this times the height).");
        prm.declare_entry(
          "Number of steps",
          "30",
          Integer(1, 100000),
          "Nominal number of load steps: the step is never "
          "larger than target / this number; it is halved "
          "when Newton fails and grows back (by the growth "
          "factor) after two consecutive steps of at most 2 iterations or a "
          "third of the "
          "maximum Newton iterations.");
        declare_solver_entries(prm);
        prm.declare_entry("Interface integration",
                          "lobatto",
                          Selection("lobatto|gauss"),
                          "Integration points of the interface elements: "
                          "`lobatto' (2 x 2 points at the nodes, avoids "
                          "traction oscillations at high penalty) or "
                          "`gauss' (2 x 2 Gauss points).");
        prm.declare_entry("Output interval",
                          "10",
                          Integer(0, 100000),
                          "Write VTU/PVTU (bricks) and VTU (interfaces) "
                          "every this many converged steps, and after the "
                          "last; 0: only the initial and the last state.");
        prm.declare_entry("Write VTU",
                          "true",
                          Bool(),
                          "Write the VTU/PVTU/PVD time series "
                          "(solution.pvd: displacement in m, stress in Pa, "
                          "MPI subdomain; interfaces.pvd: damage, normal "
                          "opening and slip in m, joint type).");
        prm.declare_entry(
          "Output format",
          "vtu",
          Selection("vtu|hdf5"),
          "Format of the brick fields when `Write VTU' is true: `vtu' "
          "writes solution.pvd with solution_NNNN.pvtu and one .vtu per "
          "rank; `hdf5' writes solution.xdmf with one solution_NNNN.h5 per "
          "output step (mesh and fields, written in parallel by all ranks; "
          "open solution.xdmf in ParaView with the XDMF reader). The "
          "interfaces are written as interfaces.pvd / interfaces_NNNN.vtu in "
          "both cases.");
        prm.declare_entry("Gauge length",
                          "0",
                          Double(0),
                          "Length of a virtual displacement transducer "
                          "(LVDT) on the front face (y = 0) at mid-length, "
                          "centred at mid-height, m (>= 0; its ends snap "
                          "to the nearest mesh points, the length used is "
                          "reported as gauge_length). Its strain along the "
                          "platen direction is written as gauge_strain in "
                          "curve.csv, with gauge_strain_at_peak and "
                          "initial_modulus_gauge in summary.json; 0: no "
                          "gauge (strain over the whole height only).");
        prm.declare_entry(
          "Joints",
          "interfaces",
          Selection("interfaces|bonded"),
          "`interfaces': every joint is a zero-thickness interface of the "
          "`Interface law'; `bonded': the bricks share the vertices of "
          "coincident faces, so the wallette is one continuum without "
          "joints (a perfectly bonded reference).");
        prm.declare_entry(
          "Splitting interfaces",
          "false",
          Bool(),
          "Potential vertical splitting cracks: each unit is meshed as two "
          "halves joined by a zero-thickness interface through its middle, "
          "normal to its longer horizontal side (in line with the head "
          "joints of the next course for a stretcher; units whose half is "
          "not a whole number of elements, such as closers, stay whole). "
          "The interface follows the composite law with the unit's tensile "
          "strength and fracture energy as its tension cut-off, Coulomb "
          "friction through the unit's uniaxial strengths (c = sqrt(f_c "
          "f_t) / 2, tan(phi) = (f_c - f_t) / (2 sqrt(f_c f_t))), G_II = 10 "
          "G_f and no cap (10 f_c); the values used are printed in log.txt "
          "and summary.json (derived_values / splitting_interfaces). Needs "
          "`Joints = interfaces'.");
        prm.declare_entry("Splitting tensile strength",
                          "0",
                          Double(0),
                          "Tensile strength of the units across a splitting "
                          "interface, Pa (>= 0; 0: the brick material's "
                          "`Tensile strength').");
        prm.declare_entry("Splitting fracture energy",
                          "0",
                          Double(0),
                          "Mode I fracture energy of the units across a "
                          "splitting interface, J/m^2 = N/m (>= 0; 0: the "
                          "brick material's `Tensile fracture energy').");
        prm.declare_entry("Splitting compressive strength",
                          "0",
                          Double(0),
                          "Compressive strength of the units for the "
                          "splitting interfaces' friction, Pa (>= 0; 0: the "
                          "brick material's `Compressive strength').");
        prm.declare_entry("Splitting stiffness",
                          "0",
                          Double(0),
                          "Normal penalty stiffness of the splitting "
                          "interfaces, Pa/m (>= 0; 0: 100 E_b / L with the "
                          "enlarged unit's length L, which adds 1 % to a "
                          "unit's compliance along its length); the shear "
                          "penalty is this / (2 (1 + nu_b)).");
        prm.declare_entry(
          "Mesh distortion",
          "0",
          Double(0, 0.2),
          "Amplitude of a smooth distortion of the hexahedra, as a "
          "fraction of the mesh spacing in each direction (dimensionless; "
          "0: the regular mesh). With `Joints = interfaces' the vertices "
          "inside each brick move by a bubble that vanishes on the brick's "
          "faces, so joint faces and the wallette's faces stay unchanged; "
          "with `Joints = bonded' one smooth map moves all vertices and "
          "keeps each face of the wallette in its plane. For patch tests "
          "(uniform compression has the same exact solution).");
        prm.declare_entry(
          "Write CalculiX input",
          "false",
          Bool(),
          "Also write calculix.inp (the mesh as C3D8 elements, the brick "
          "material, the platen conditions and the final platen displacement "
          "as one linear static step, for `ccx -i calculix') and "
          "nodal_displacements.csv (this run's final displacements, m, in "
          "the same node numbering). Needs `Joints = bonded' and an elastic "
          "brick material.");
        prm.declare_entry(
          "Protocol",
          "monotonic",
          Selection("monotonic|cyclic"),
          "`monotonic': the top platen moves to the target strain in one "
          "ramp. `cyclic': load-unload cycles at increasing amplitudes "
          "(`Cycle amplitudes'), each unloaded under displacement control "
          "until the stress has dropped to `Unloading stress'; cycles.csv "
          "and envelope.csv give per cycle the peak stress, residual "
          "strain, unloading modulus and dissipated energy, and the "
          "envelope, common-point and stability-point stresses.");
        prm.declare_entry(
          "Cycle amplitudes",
          "",
          dealii::Patterns::List(Double(0)),
          "Strains (platen displacement / height, dimensionless, "
          "increasing) at which the cycles of the `cyclic' protocol turn "
          "back. Empty: k times `Amplitude increment' for k = 1, 2, ... up "
          "to `Target strain'.");
        prm.declare_entry("Amplitude increment",
                          "0.0005",
                          Double(0),
                          "Strain added from one amplitude to the next when "
                          "`Cycle amplitudes' is empty (dimensionless, > 0).");
        prm.declare_entry("Cycles per amplitude",
                          "1",
                          Integer(1, 100),
                          "Load-unload cycles at each amplitude; 2 or more "
                          "give the common-point and stability-point "
                          "curves.");
        prm.declare_entry("Unloading stress",
                          "0.1e6",
                          Double(0),
                          "An unloading ends when the stress (platen force "
                          "/ gross area) has dropped to this, Pa (>= 0): "
                          "the small target force of a test. Its last step "
                          "is aimed at it; the leg ends at the first step "
                          "at or below 1.01 times it.");
        prm.declare_entry(
          "Collapse stress ratio",
          "0",
          Double(0, 1),
          "The run ends when the specimen has collapsed: on a loading leg "
          "the stress has fallen below this fraction r of the peak stress "
          "of the run, and it lies more than r times the peak below the "
          "largest stress of the leg (a reloading from the unloading stress "
          "is not a collapse), dimensionless, in [0, 1). In a monotonic run "
          "that is a stress below min(r, 1 - r) times the peak, so 0.5 ends "
          "it at half the peak. Its status is `completed', its message "
          "(log.txt, summary.json) says where, and the last state is written; "
          "the rest of the protocol is not run. 0: never (the run goes on "
          "to the last amplitude whatever the specimen still carries).");
        prm.declare_entry(
          "Platen speed",
          "1e-5",
          Double(0),
          "Speed of the top platen, m/s (> 0): the pseudo-time of a step "
          "is its platen displacement / this speed. It matters only for "
          "the viscous regularisation of the brick and joint damage "
          "(`Viscosity' of the material and the interface law).");
        prm.declare_entry(
          "Deletion strain",
          "0",
          Double(0),
          "Element deletion: after a converged step, cells whose maximum "
          "principal strain (of the cell-averaged strain, dimensionless) "
          "exceeds this are removed from the model, the largest first, at "
          "most `Maximum deletions per step' at a time; joints at a deleted "
          "cell go with it, and nodes left without a cell are held where "
          "they are. 0: no deletion. Deleted cells are flagged in "
          "solution.pvd (`deleted') and counted in curve.csv.");
        prm.declare_entry(
          "Deletion fade opening",
          "0",
          Double(0),
          "Gradual deletion, m (>= 0): a cell past `Deletion strain' fades "
          "out instead of going at once: its stress and stiffness are "
          "scaled by 1 - (e1 - Deletion strain) l / this, with e1 the "
          "largest cell-averaged principal strain it has reached and l its "
          "crack-band length (the cube root of its volume; a mortar cell: "
          "its size across the layer) (crack band: the fade ends at the same "
          "lateral opening whatever the mesh); it is deleted when the "
          "factor reaches 0, then carrying nothing. 0: deleted at once. "
          "The fade of every cell is written to solution.pvd (`fade').");
        prm.declare_entry(
          "Deletion crushing length",
          "0",
          Double(0),
          "Crushing of split cells, m (>= 0): a cell past `Deletion "
          "strain' (split) also fades with its shortening since then: its "
          "factor is at most 1 - (s - s_split) l / this, with s the largest "
          "compressive principal strain of the cell, s_split its value when "
          "the cell passed `Deletion strain' and l its crack-band length "
          "(the cube root of its volume; a mortar cell: its size across "
          "the layer) (crack band: the split column crushes over this "
          "shortening whatever the mesh; a cell at stress f fading linearly "
          "dissipates f x this / 2 per unit area, so 2 G_fc / f_b gives the "
          "unit's compressive fracture energy); it is deleted when the "
          "factor reaches 0. 0: no crushing fade.");
        prm.declare_entry(
          "Deletion stress",
          "0",
          Double(0),
          "Deletion only of cells that carry nothing, Pa (>= 0): a cell "
          "past `Deletion strain' (or at the end of its fade) is deleted "
          "only once the largest absolute principal value of its "
          "cell-averaged stress is at most this; until then it stays, "
          "whatever its strain. 0: no such condition (a cell goes when its "
          "strain passes the threshold, whatever it carries).");
        prm.declare_entry("Maximum deletions per step",
                          "10",
                          Integer(1, 100000),
                          "Cap of the cells deleted after one step.");
        prm.declare_entry(
          "Strength scatter",
          "0",
          Double(0, 0.5),
          "Coefficient of variation of the strengths (dimensionless, 0 to "
          "0.5; 0: every brick and joint has the nominal strengths). Each "
          "brick and each joint (pair of bricks) draws a normal factor 1 + "
          "this x N(0, 1), kept within 0.2 to 1.8, on its strengths "
          "(a specimen of a series).");
        prm.declare_entry("Random seed",
                          "1",
                          Integer(0),
                          "Seed of the strength factors: the same seed gives "
                          "the same specimen.");
        prm.declare_entry(
          "Checkpoint interval",
          "0",
          Integer(0),
          "Write the state (displacements, brick and joint histories, "
          "deleted cells, protocol position, curve) to checkpoint.RANK in "
          "the output directory every this many converged steps (0: only "
          "when the run stops early: no convergence or `Maximum steps').");
        prm.declare_entry(
          "Resume",
          "false",
          Bool(),
          "Continue from the checkpoint in the output directory (written "
          "by an earlier run of the same parameter file with the same "
          "number of MPI ranks) instead of starting from zero; the curve "
          "and results continue as if the run had not stopped.");
        prm.declare_entry("Maximum steps",
                          "0",
                          Integer(0),
                          "Stop after this many converged steps of this run "
                          "with status `interrupted' and a checkpoint (0: no "
                          "limit); `Resume = true' continues.");
        prm.declare_entry(
          "Damage integration",
          "implicit",
          Selection("implicit|implex"),
          "`implicit': the brick and joint laws are integrated implicitly "
          "(Newton with their algorithmic tangents). `implex': IMPL-EX "
          "(Oliver, Huespe & Cante 2008): within a step the damages and "
          "plastic strains are extrapolated linearly in pseudo-time from "
          "the two last converged steps and frozen, so the step is (nearly) "
          "linear, with a positive tangent; after the step the laws are "
          "updated implicitly at the converged displacements. The step "
          "size follows `IMPL-EX damage tolerance' (never larger than the "
          "nominal step).");
        prm.declare_entry(
          "IMPL-EX damage tolerance",
          "0.05",
          Double(0),
          "IMPL-EX step control (dimensionless, > 0): when the largest "
          "difference between the updated and the extrapolated damage of "
          "a step exceeds this, the step is redone smaller in proportion "
          "(to no less than a fifth, and not below `IMPL-EX minimum step'; "
          "`implex_steps_redone' in summary.json); below half of it, the "
          "next step grows by `Step growth factor' up to the nominal "
          "step.");
        prm.declare_entry(
          "IMPL-EX minimum step",
          "0.01",
          Double(0, 1),
          "Smallest step the IMPL-EX step control asks for, as a fraction "
          "of the nominal step (dimensionless, 0 < value <= 1). Where a "
          "joint or a brick point snaps (its damage jumps whatever the "
          "step), the damage error stays above the tolerance for any step; "
          "at this floor such steps are accepted and counted "
          "(`implex_steps_over_tolerance' in summary.json) instead of "
          "shrinking the step towards zero. Cut-backs after a failed Newton "
          "solve are not limited by it.");
        prm.declare_entry("Write plot",
                          "true",
                          Bool(),
                          "Draw the stress-strain curve into curve.png "
                          "(matplotlib, /usr/bin/python3).");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        const double joint    = prm.get_double("Joint thickness");
        auto         positive = [&](const std::string &entry) {
          return positive_entry(prm, entry);
        };
        s.mesh.size.length      = positive("Brick length") + joint;
        s.mesh.size.width       = positive("Brick width") + joint;
        s.mesh.size.height      = positive("Brick height") + joint;
        s.mesh.size.courses     = prm.get_integer("Courses");
        s.mesh.size.bricks_long = prm.get_integer("Length in bricks");
        s.mesh.n_l              = prm.get_integer("Elements along the length");
        s.mesh.n_w              = prm.get_integer("Elements along the width");
        s.mesh.n_h              = prm.get_integer("Elements along the height");
        s.platen.lateral_fixed = prm.get("Platen lateral restraint") == "fixed";
        const auto dir =
          split_doubles(prm.get("Platen direction"), "Platen direction");
        const double norm =
          std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        AssertThrow(norm > 0,
                    ExcParameter("Platen direction", "must not be zero"));
        for (unsigned int d = 0; d < 3; ++d)
          s.platen.direction[d] = dir[d] / norm;
        AssertThrow(s.platen.lateral_fixed || (dir[0] == 0 && dir[1] == 0),
                    ExcParameter("Platen direction",
                                 "a sideways motion needs `Platen lateral "
                                 "restraint = fixed'"));
        target_strain      = positive("Target strain");
        s.protocol.n_steps = prm.get_integer("Number of steps");
        parse_solver_entries(prm, s);
        s.mesh.gauss            = prm.get("Interface integration") == "gauss";
        s.output.vtu_interval   = prm.get_integer("Output interval");
        s.output.write_vtu      = prm.get_bool("Write VTU");
        s.output.hdf5           = prm.get("Output format") == "hdf5";
        s.output.write_plot     = prm.get_bool("Write plot");
        s.mesh.bonded           = prm.get("Joints") == "bonded";
        s.output.write_calculix = prm.get_bool("Write CalculiX input");
        AssertThrow(!s.output.write_calculix || s.mesh.bonded,
                    ExcParameter("Write CalculiX input",
                                 "needs `Joints = bonded' (CalculiX has no "
                                 "interfaces of this model)"));
        s.platen.gauge_length = prm.get_double("Gauge length");
        cyclic                = prm.get("Protocol") == "cyclic";
        amplitudes =
          split_doubles(prm.get("Cycle amplitudes"), "Cycle amplitudes");
        amplitude_increment = positive("Amplitude increment");
        s.protocol.cycles_per_amplitude =
          prm.get_integer("Cycles per amplitude");
        s.protocol.unloading_stress = prm.get_double("Unloading stress");
        s.protocol.platen_speed     = positive("Platen speed");
        s.protocol.collapse_ratio   = prm.get_double("Collapse stress ratio");
        AssertThrow(s.protocol.collapse_ratio < 1,
                    ExcParameter("Collapse stress ratio",
                                 "must be below 1 (a fraction of the peak)"));
        s.specimen.deletion_strain = prm.get_double("Deletion strain");
        s.specimen.deletion_fade_opening =
          prm.get_double("Deletion fade opening");
        s.specimen.deletion_crushing_length =
          prm.get_double("Deletion crushing length");
        s.specimen.deletion_stress = prm.get_double("Deletion stress");
        s.specimen.max_deletions =
          prm.get_integer("Maximum deletions per step");
        s.specimen.strength_scatter = prm.get_double("Strength scatter");
        s.specimen.seed             = prm.get_integer("Random seed");
        s.checkpoint.checkpoint_interval =
          prm.get_integer("Checkpoint interval");
        s.checkpoint.resume  = prm.get_bool("Resume");
        s.protocol.max_steps = prm.get_integer("Maximum steps");
        s.integrator.implex  = prm.get("Damage integration") == "implex";
        s.integrator.implex_tolerance    = positive("IMPL-EX damage tolerance");
        s.integrator.implex_minimum_step = positive("IMPL-EX minimum step");
        for (unsigned int i = 1; i < amplitudes.size(); ++i)
          AssertThrow(amplitudes[i] > amplitudes[i - 1],
                      ExcParameter("Cycle amplitudes",
                                   "must increase from one cycle to the "
                                   "next"));
        AssertThrow(amplitudes.empty() || amplitudes[0] > 0,
                    ExcParameter("Cycle amplitudes", "must be positive"));
        AssertThrow(!cyclic || !s.output.write_calculix,
                    ExcParameter("Write CalculiX input",
                                 "needs the monotonic protocol"));
        s.mesh.distortion       = prm.get_double("Mesh distortion");
        s.mesh.split_units      = prm.get_bool("Splitting interfaces");
        s.mesh.detailed         = prm.get("Model") == "detailed";
        s.mesh.mortar_thickness = joint;
        AssertThrow(!s.mesh.detailed || joint > 0,
                    ExcParameter("Joint thickness",
                                 "must be positive with `Model = detailed' "
                                 "(the mortar layer's thickness)"));
        // sizes too small to mesh (1e-30 m gave units or mortar of no cells)
        for (const std::string e :
             {"Brick length", "Brick width", "Brick height", "Joint thickness"})
          AssertThrow(
            prm.get_double(e) >= 1e-6 || (e[0] == 'J' && !s.mesh.detailed),
            ExcParameter(e, "must be at least 1e-6 m, got " + prm.get(e)));
        for (const char *entry : {"Head joint fill", "Collar joint fill"})
          {
            const double f = prm.get_double(entry);
            AssertThrow(f >= 0 && f <= 1,
                        ExcParameter(entry, "must lie in [0, 1]"));
            AssertThrow(f == 1 || s.mesh.detailed,
                        ExcParameter(entry, "needs `Model = detailed'"));
            (entry[0] == 'H' ? s.mesh.head_joint_fill :
                               s.mesh.collar_joint_fill) = f;
          }
        s.mesh.collar_bed_gap = prm.get_double("Collar bed gap");
        AssertThrow(s.mesh.collar_bed_gap >= 0,
                    ExcParameter("Collar bed gap", "must not be negative"));
        AssertThrow(s.mesh.collar_bed_gap == 0 || s.mesh.detailed,
                    ExcParameter("Collar bed gap", "needs `Model = detailed'"));
        AssertThrow(!s.mesh.detailed || s.mesh.distortion == 0,
                    ExcParameter("Mesh distortion",
                                 "is not supported with `Model = detailed'"));
        AssertThrow(!s.mesh.split_units || !s.mesh.bonded,
                    ExcParameter("Splitting interfaces",
                                 "needs `Joints = interfaces'"));
        splitting.tensile_strength =
          prm.get_double("Splitting tensile strength");
        splitting.fracture_energy = prm.get_double("Splitting fracture energy");
        splitting.compressive_strength =
          prm.get_double("Splitting compressive strength");
        splitting.stiffness = prm.get_double("Splitting stiffness");
      }

      void
      setup(dealii::ParameterHandler &prm) override
      {
        bond     = plugins::Registry<brickwork::Bond>::create(prm);
        material = plugins::Registry<brickwork::BrickMaterial>::create(prm);
        if (s.mesh.detailed)
          {
            using Materials = plugins::Registry<brickwork::BrickMaterial>;
            mortar          = Materials::create(prm,
                                       Materials::selected(prm, mortar_section),
                                       mortar_section);
          }
        law = plugins::Registry<brickwork::InterfaceLaw>::create(prm);
        // (checked again by run_wallette() for callers of the library)
        AssertThrow(
          material->nonlocal_length() == 0 || s.integrator.implex,
          ExcParameter("Nonlocal length",
                       "a value > 0 needs `Damage integration = implex'"));
        AssertThrow(
          material->nonlocal_length() == 0 ||
            !s.integrator.implex_floor_correction,
          ExcParameter("Nonlocal length",
                       "a value > 0 needs `IMPL-EX floor correction = "
                       "accept'"));
        make_postprocessors(prm);
        // lay the bricks now so that --validate finds a mesh that does not
        // fit the bond
        plugins::ParsePathScope scope("Wallette");
        boxes = bond->layout(s.mesh.size);
        if (!s.mesh.detailed)
          brickwork::check_mesh(boxes, s.mesh);
        // (the detailed model's units are one joint shorter)
        if (s.mesh.split_units)
          splitting_law = brickwork::make_splitting_law(
            splitting,
            *material,
            s.mesh.size.length -
              (s.mesh.detailed ? s.mesh.mortar_thickness : 0.));
        // the height of the wallette (the detailed one's top course has no
        // bed joint above it)
        const double H = s.mesh.size.height * s.mesh.size.courses -
                         (s.mesh.detailed ? s.mesh.mortar_thickness : 0.);
        s.protocol.target_displacement = target_strain * H;
        s.protocol.cycle_amplitudes.clear();
        if (cyclic)
          {
            if (amplitudes.empty())
              for (unsigned int k = 1;
                   k * amplitude_increment <= target_strain * (1 + 1e-9);
                   ++k)
                s.protocol.cycle_amplitudes.push_back(k * amplitude_increment *
                                                      H);
            else
              for (const double a : amplitudes)
                s.protocol.cycle_amplitudes.push_back(a * H);
            AssertThrow(!s.protocol.cycle_amplitudes.empty(),
                        ExcParameter("Amplitude increment",
                                     "is larger than the target strain: no "
                                     "cycle"));
            s.protocol.target_displacement = s.protocol.cycle_amplitudes.back();
          }
      }

      void
      run(RunContext &context) override
      {
        brickwork::run_wallette(boxes,
                                *material,
                                *law,
                                s,
                                postprocessors,
                                context,
                                splitting_law.get(),
                                mortar.get());
      }

    private:
      /**
       * The listed postprocessors: `curve tables' first (the curve and the
       * summary the others use), `fields' and `joint fields' only with
       * `Write VTU', `curve plot' only with `Write plot', `calculix' also
       * with `Write CalculiX input'.
       */
      void
      make_postprocessors(dealii::ParameterHandler &prm)
      {
        using Family      = brickwork::postprocess::Postprocessor;
        auto       listed = plugins::Registry<Family>::create_selected(prm);
        const auto wanted = [&](const std::string &name) {
          if (name == "fields" || name == "joint fields")
            return s.output.write_vtu;
          if (name == "curve plot")
            return s.output.write_plot;
          return true;
        };
        const auto add = [&](const std::string &name) {
          for (auto &p : listed)
            if (p.first == name && p.second)
              {
                postprocessors.push_back(std::move(p.second));
                return true;
              }
          return false;
        };
        if (!add("curve tables"))
          postprocessors.push_back(
            plugins::Registry<Family>::create(prm, "curve tables"));
        for (auto &p : listed)
          if (p.second && wanted(p.first))
            postprocessors.push_back(std::move(p.second));
        bool calculix = false;
        for (const auto &p : listed)
          calculix = calculix || p.first == "calculix";
        if (s.output.write_calculix && !calculix)
          postprocessors.push_back(
            plugins::Registry<Family>::create(prm, "calculix"));
      }

      brickwork::WalletteSettings               s;
      double                                    target_strain = 0.003;
      bool                                      cyclic        = false;
      std::vector<double>                       amplitudes;
      double                                    amplitude_increment = 0;
      std::unique_ptr<brickwork::Bond>          bond;
      std::unique_ptr<brickwork::BrickMaterial> material;
      /** The mortar's material (`Model = detailed'), else nullptr. */
      std::unique_ptr<brickwork::BrickMaterial> mortar;
      std::unique_ptr<brickwork::InterfaceLaw>  law;
      brickwork::SplittingSettings              splitting;
      std::unique_ptr<brickwork::InterfaceLaw>  splitting_law;
      std::vector<brickwork::Box>               boxes;
      std::vector<std::unique_ptr<brickwork::postprocess::Postprocessor>>
        postprocessors;
    };
  } // namespace analysis
} // namespace masonry

MASONRY_REGISTER_ANALYSIS(
  masonry::analysis::WalletteCompression,
  "wallette",
  "Mesoscale model of a bonded brickwork wallette (prism) between rigid "
  "platens: enlarged bricks (brick plus half joint) of 8-node hexahedra, "
  "joints as zero-thickness interfaces (`Interface law'), bricks from "
  "`Brick material', laid in the `Bond' pattern. The bottom platen is "
  "fixed, the top one moves under displacement control, monotonically to "
  "the target strain or in load-unload cycles (`Protocol'), solved by "
  "Newton-Raphson with line search and adaptive steps; cells can be "
  "deleted at a threshold strain. Writes curve.csv (stress = platen force "
  "/ gross area, strain = platen displacement / height), curve.png, "
  "cycles.csv, envelope.csv and degradation.png (cyclic), VTU time series "
  "and summary.json (peak_stress in Pa, strain_at_peak, initial_modulus in "
  "Pa, joint counts, steps, Newton iterations, cut-backs, deleted cells, "
  "seconds). Checkpoints allow a stopped run to resume.")
