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
#include <masonry/core/parameters.h>

#include <algorithm>

#include "../brickwork/laws/splitting.h"
#include "../brickwork/wallette.h"

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

      /** The splitting interfaces through the units: an interface law of
       * their own. */
      const char *const splitting_section = "Splitting interface law";
      /** The selection of the law derived from the units (the default). */
      const char *const from_units = "from the units";

      void
      declare_splitting_law(dealii::ParameterHandler &prm)
      {
        using Laws = plugins::Registry<brickwork::InterfaceLaw>;
        Laws::declare_parameters(prm, splitting_section);
        // the family's entry, declared again with the derived law as the
        // default and the splitting interfaces' own text
        prm.enter_subsection(splitting_section);
        prm.declare_entry(
          "Law",
          from_units,
          dealii::Patterns::Selection(std::string(from_units) + "|" +
                                      Laws::pattern()),
          Laws::documentation(
            "The law of the splitting interfaces through the units "
            "(`subsection Wallette/Splitting interfaces = true'). `from the "
            "units' (the default): the composite law with the units' "
            "tensile strength and fracture energy and Coulomb friction "
            "through their uniaxial strengths, derived from the brick "
            "material unless the `Splitting ...' entries of subsection "
            "Wallette give the values (doc/brickwork.md, Splitting "
            "interfaces); the entries of this subsection are then not used. "
            "Any interface law below: that law, with its entries in this "
            "subsection, `Normal stiffness' and `Shear stiffness' included "
            "(their defaults are a bed joint's, not the derived 100 E_b / "
            "L)."));
        prm.leave_subsection();
      }

      [[maybe_unused]] const bool splitting_declared =
        (plugins::add_subsystem(
           {splitting_section, "Law", &declare_splitting_law}),
         true);
    } // namespace

    /**
     * A wallette of enlarged bricks joined by zero-thickness cohesive
     * interfaces, loaded by a top platen moving by a prescribed
     * displacement; the bottom platen is fixed. The entries of `subsection
     * Wallette' belong to the parts of the model (WalletteSettings) and to
     * the protocol, integrator and linear solver plugins, each declared
     * and read next to the part it sets.
     */
    class WalletteCompression : public Interface
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        brickwork::WalletteSettings::declare_parameters(prm);
        prm.declare_entry("Splitting tensile strength",
                          "0",
                          Double(0),
                          "Tensile strength of the units across a splitting "
                          "interface, Pa (>= 0; 0: the brick material's "
                          "`Tensile strength'), with `Splitting interface "
                          "law/Law = from the units'.");
        prm.declare_entry("Splitting fracture energy",
                          "0",
                          Double(0),
                          "Mode I fracture energy of the units across a "
                          "splitting interface, J/m^2 = N/m (>= 0; 0: the "
                          "brick material's `Tensile fracture energy'), "
                          "with `Splitting interface law/Law = from the "
                          "units'.");
        prm.declare_entry("Splitting compressive strength",
                          "0",
                          Double(0),
                          "Compressive strength of the units for the "
                          "splitting interfaces' friction, Pa (>= 0; 0: the "
                          "brick material's `Compressive strength'), with "
                          "`Splitting interface law/Law = from the units'.");
        prm.declare_entry("Splitting stiffness",
                          "0",
                          Double(0),
                          "Normal penalty stiffness of the splitting "
                          "interfaces, Pa/m (>= 0; 0: 100 E_b / L with the "
                          "enlarged unit's length L, which adds 1 % to a "
                          "unit's compliance along its length); the shear "
                          "penalty is this / (2 (1 + nu_b)); with "
                          "`Splitting interface law/Law = from the units'.");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        s.parse_parameters(prm);
        AssertThrow(!s.output.write_calculix || s.mesh.bonded,
                    ExcParameter("Write CalculiX input",
                                 "needs `Joints = bonded' (CalculiX has no "
                                 "interfaces of this model)"));
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
        law      = plugins::Registry<brickwork::InterfaceLaw>::create(prm);
        protocol = plugins::Registry<brickwork::Protocol>::create(prm);
        integrator =
          plugins::Registry<brickwork::model::Integrator>::create(prm);
        solver = plugins::Registry<brickwork::LinearSolver>::create(prm);
        // (checked again by run_wallette() for callers of the library)
        AssertThrow(
          brickwork::nonlocal_length(*material) == 0 ||
            integrator->updates_after_step(),
          ExcParameter("Nonlocal length",
                       "a value > 0 needs `Damage integration = implex'"));
        AssertThrow(
          brickwork::nonlocal_length(*material) == 0 ||
            !s.steps.implex_floor_correction,
          ExcParameter("Nonlocal length",
                       "a value > 0 needs `IMPL-EX floor correction = "
                       "accept'"));
        make_postprocessors(prm);
        plugins::ParsePathScope scope("Wallette");
        // lay the bricks now so that --validate finds a mesh that does not
        // fit the bond
        boxes = bond->layout(s.mesh.size);
        if (!s.mesh.detailed)
          brickwork::check_mesh(boxes, s.mesh);
        else
          brickwork::check_units(boxes, s.mesh);
        // (the detailed model's units are one joint shorter)
        using Laws = plugins::Registry<brickwork::InterfaceLaw>;
        splitting_choice =
          s.mesh.split_units ? Laws::selected(prm, splitting_section) : "";
        if (splitting_choice == from_units)
          splitting_law = brickwork::make_splitting_law(
            splitting,
            *material,
            "Brick material/" +
              plugins::section_name(
                plugins::Registry<brickwork::BrickMaterial>::selected(prm)),
            s.mesh.size.length -
              (s.mesh.detailed ? s.mesh.mortar_thickness : 0.));
        else if (s.mesh.split_units)
          splitting_law =
            Laws::create(prm, splitting_choice, splitting_section);
        make_law_set();
        // (checked again by run_wallette(): here for --validate)
        brickwork::check_laws(laws, *integrator, s);
        // the height of the wallette (the detailed one's top course has no
        // bed joint above it)
        protocol->initialize(s.mesh.size.height * s.mesh.size.courses -
                             (s.mesh.detailed ? s.mesh.mortar_thickness : 0.));
        AssertThrow(!protocol->is_cyclic() || !s.output.write_calculix,
                    ExcParameter("Write CalculiX input",
                                 "needs the monotonic protocol"));
      }

      void
      check_output_directory(const std::string &directory,
                             const MPI_Comm     comm) const override
      {
        // a resume needs a readable checkpoint there, of a run with the
        // same entries, found before the driver replaces the stopped run's
        // summary.json and log.txt
        if (s.checkpoint.resume)
          {
            plugins::ParsePathScope scope("Wallette");
            brickwork::model::check_checkpoint(directory,
                                               s.checkpoint.inputs,
                                               comm);
          }
      }

      void
      run(RunContext &context) override
      {
        brickwork::run_wallette(
          boxes,
          laws,
          s,
          {*protocol, *integrator, *solver, postprocessors},
          context);
      }

    private:
      /** The laws by cell region and joint type, each named by the entry
       * that selects it. */
      void
      make_law_set()
      {
        laws.add_region_law(*material, "Brick material/Model", "");
        if (mortar)
          laws.add_region_law(*mortar, "Mortar material/Model", "mortar_");
        // bed, head and collar joints
        laws.add_joint_law({0, 1, 2}, *law, "Interface law/Law", "");
        if (splitting_law)
          laws.add_joint_law({brickwork::model::splitting_type},
                             *splitting_law,
                             splitting_choice == from_units ?
                               "Wallette/Splitting interfaces" :
                               std::string(splitting_section) + "/Law",
                             "splitting_");
      }

      /**
       * The listed postprocessors in their order, `curve tables' also when
       * not listed (curve.csv is always written), `fields' and `joint
       * fields' only with `Write VTU', `curve plot' only with `Write plot',
       * `calculix' also with `Write CalculiX input'.
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
        bool tables = false;
        for (const auto &p : listed)
          tables = tables || p.first == "curve tables";
        if (!tables)
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
      std::unique_ptr<brickwork::Bond>          bond;
      std::unique_ptr<brickwork::BrickMaterial> material;
      /** The mortar's material (`Model = detailed'), else nullptr. */
      std::unique_ptr<brickwork::BrickMaterial>     mortar;
      std::unique_ptr<brickwork::InterfaceLaw>      law;
      std::unique_ptr<brickwork::Protocol>          protocol;
      std::unique_ptr<brickwork::model::Integrator> integrator;
      std::unique_ptr<brickwork::LinearSolver>      solver;
      brickwork::SplittingSettings                  splitting;
      std::unique_ptr<brickwork::InterfaceLaw>      splitting_law;
      /** `Splitting interface law/Law' ("" without splitting
       * interfaces). */
      std::string                 splitting_choice;
      brickwork::LawSet           laws;
      std::vector<brickwork::Box> boxes;
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
