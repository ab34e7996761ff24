/**
 * @file
 * Interface models of rigid-block analyses: the strength of the joints
 * between blocks and with the supports (`subsection Interface model`).
 *
 * A model is a convex yield surface of the traction at a contact point,
 * linearised into planes @f$a_k \cdot \sigma \le b_k@f$ in the point's local
 * frame (normal, across, along) with @f$\sigma = (\sigma_n, \tau_a,
 * \tau_l)@f$, tension positive. The flow rule is associative: the jump rate
 * of the contact point is @f$[u] = \sum_k \lambda_k a_k@f$ with
 * @f$\lambda_k \ge 0@f$, and the dissipation is @f$A \sum_k \lambda_k
 * b_k@f$ with A the point's tributary area.
 */
#ifndef masonry_rigid_blocks_interface_model_h
#define masonry_rigid_blocks_interface_model_h

#include <masonry/core/plugins.h>

#include <deal.II/base/tensor.h>

#include <vector>

namespace masonry
{
  namespace rigid_blocks
  {
    /** One plane a·σ ≤ b of a linearised yield surface. */
    struct YieldPlane
    {
      /** Outward normal in the local frame (normal, across, along). */
      dealii::Tensor<1, 3> a;
      /** Right-hand side, Pa (dissipation per unit area and unit λ). */
      double b;
    };

    /**
     * Base class of interface models. Create one with
     * `plugins::Registry<rigid_blocks::InterfaceModel>::create(prm)`.
     */
    class InterfaceModel : public plugins::InterfaceBase
    {
    public:
      /** Parameters live in `subsection Interface model`. */
      static constexpr const char *registry_section = "Interface model";
      /** The selection entry: `set Model = ...`. */
      static constexpr const char *registry_entry = "Model";
      /** Default selection: "no tension no sliding". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();


      /** Read the model's own subsection. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override = 0;

      /** The planes of the linearised yield surface. */
      virtual const std::vector<YieldPlane> &
      yield_planes() const = 0;

      /**
       * True if the admissible jumps are exactly {opening ≥ 0, no sliding}
       * at no dissipation: the LP then states them as rows without
       * multipliers (fewer columns, the same optimum).
       */
      virtual bool
      no_tension_no_sliding() const;
    };
  } // namespace rigid_blocks
} // namespace masonry

/** Register an interface model (one line in the model's .cc file). */
#define MASONRY_REGISTER_INTERFACE_MODEL(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::rigid_blocks::InterfaceModel,       \
                          classname,                                   \
                          name,                                        \
                          description)

#endif
