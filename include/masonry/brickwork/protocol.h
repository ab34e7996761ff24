/**
 * @file
 * The loading protocol of a wallette (`subsection Wallette / set Protocol =
 * ...`): the path of the top platen in pseudo-time as a list of legs
 * (loading to a displacement, unloading to a force) and how the platen
 * holds the top face. A plugin family: a new protocol is one file with a
 * class derived from Protocol and one MASONRY_REGISTER_PROTOCOL line
 * (source/brickwork/protocols/monotonic.cc is the smallest; a test defines
 * one whose platen is free to tilt, tests/brickwork_free_rotation.cc). The
 * protocols' entries stand in `subsection Wallette' next to the analysis's
 * own.
 */
#ifndef masonry_brickwork_protocol_h
#define masonry_brickwork_protocol_h

#include <masonry/brickwork/curve.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    /** One leg of the platen's path. */
    struct Leg
    {
      /** Platen displacement to reach (loading) or the lowest allowed
       * (unloading), m along the platen direction. */
      double target = 0;
      /** Whether the platen moves back (towards smaller displacements). */
      bool unloading = false;
      /** The load-unload cycle the leg belongs to (from 1). */
      unsigned int cycle = 1;
    };

    /** The top platen as a protocol sees it. */
    struct Platen
    {
      /** The nodes of the top face: position (m) and DoFs (x, y, z). */
      std::vector<dealii::Point<3>>                               positions;
      std::vector<std::array<dealii::types::global_dof_index, 3>> dofs;
      /** Unit direction of the platen's motion. */
      std::array<double, 3> direction{{0, 0, -1}};
      /** The platen holds the face in all directions (`Platen lateral
       * restraint = fixed'), or only along z. */
      bool lateral_fixed = true;
      /** Centre of the top face, m. */
      dealii::Point<3> centre;
    };

    /**
     * Base class of the protocols. The step controller asks a protocol
     * for its legs and, leg by leg, for the next platen position; a leg
     * ends when leg_done() says so. What the protocol does not override
     * is a rigid platen that moves along its direction by the protocol's
     * displacement.
     */
    class Protocol : public plugins::InterfaceBase
    {
    public:
      /** The selection `set Protocol = ...' stands in `subsection
       * Wallette', with the protocols' own entries. */
      static constexpr const char *registry_section  = "Wallette";
      static constexpr const char *registry_entry    = "Protocol";
      static constexpr bool        shared_subsection = true;
      /** Default selection: "monotonic". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();
      /** `Target strain' and `Platen speed'. */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      /** Read `Target strain' and `Platen speed'. */
      void
      parse_common_parameters(dealii::ParameterHandler &prm) override;

      /**
       * The wallette is @p height m high: turn the strains of the entries
       * into platen displacements (m). Errors name the entry.
       */
      virtual void
      initialize(const double height) = 0;

      /** The legs in order. */
      virtual std::vector<Leg>
      legs() const = 0;

      /** The platen displacement at which cycle @p cycle (from 1) turns
       * back, m. */
      virtual double
      amplitude(const unsigned int cycle) const = 0;

      /** Load-unload cycles at each amplitude (1: every cycle has its
       * own). */
      virtual unsigned int
      cycles_per_amplitude() const;

      /** Whether the platen comes back (load-unload cycles). */
      bool
      is_cyclic() const;

      /** One line about the protocol for the screen before the first step
       * ("" by default). */
      virtual std::string
      description() const;

      /** The largest platen displacement of the protocol, m (the nominal
       * step is this over `Number of steps'). */
      virtual double
      target_displacement() const = 0;

      /** The pseudo-time of a platen displacement of @p increment m, s
       * (`Platen speed'). */
      double
      pseudo_time(const double increment) const;

      /**
       * Whether @p leg has reached its end at the platen displacement
       * @p applied with the converged @p curve so far; @p nominal: the
       * nominal step, m. A loading leg ends at its target; an unloading
       * leg is the protocol's (none by default).
       */
      virtual bool
      leg_done(const Leg                     &leg,
               const std::vector<CurvePoint> &curve,
               const double                   applied,
               const double                   nominal) const;

      /**
       * The platen displacement of the next step of @p leg from
       * @p applied with the step size @p increment, m; false when the leg
       * ends here (the step would be of nothing). A loading leg goes
       * @p increment further, but not past its target.
       */
      virtual bool
      next_position(const Leg                     &leg,
                    const std::vector<CurvePoint> &curve,
                    const double                   applied,
                    const double                   increment,
                    const double                   nominal,
                    double                        &next) const;

      /**
       * The conditions of the top platen on the Newton increments into
       * @p constraints: by default every DoF of @p platen along which it
       * holds the face is fixed (a rigid platen that neither tilts nor,
       * if fixed laterally, slides).
       */
      virtual void
      hold_platen(const Platen                      &platen,
                  dealii::AffineConstraints<double> &constraints) const;

      /**
       * The displacements of the top face at the platen displacement
       * @p displacement (m along the direction) into @p u, the last
       * converged solution; by default the fixed DoFs of hold_platen() are
       * set to @p displacement times the direction.
       */
      virtual void
      move_platen(const Platen                            &platen,
                  const double                             displacement,
                  const dealii::AffineConstraints<double> &constraints,
                  dealii::TrilinosWrappers::MPI::Vector   &u) const;

    protected:
      /** `Target strain', dimensionless. */
      double target_strain = 0.003;
      /** `Platen speed', m/s. */
      double platen_speed = 1e-5;
    };
  } // namespace brickwork
} // namespace masonry

/** Register a protocol (one line in its .cc file). */
#define MASONRY_REGISTER_PROTOCOL(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::Protocol,         \
                          classname,                            \
                          name,                                 \
                          description)

#endif
