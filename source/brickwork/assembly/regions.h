/**
 * @file
 * The material of the detailed model: the units' law and the mortar's law
 * behind one BrickMaterial, chosen per point by BrickPoint::region. A
 * point's state holds both laws' states (the units' first); each point uses
 * the part of its region, the other part keeps its initial values. The
 * mortar's state variables, reported quantities and damages carry the prefix
 * `mortar_'.
 */
#ifndef masonry_brickwork_model_regions_h
#define masonry_brickwork_model_regions_h

#include <masonry/brickwork/brick_material.h>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** BrickPoint::region of the mortar cells. */
      constexpr unsigned int mortar_region = 1;

      /** Units and mortar as one material (see the file's description). */
      class RegionMaterial : public BrickMaterial
      {
      public:
        RegionMaterial(const BrickMaterial &unit, const BrickMaterial &mortar);

        std::vector<StateVariable>
        state_variables() const override;
        void
        initial_state(StateView state) const override;
        std::vector<std::string>
        reported_quantities() const override;
        void
        report(ConstStateView            state,
               dealii::ArrayView<double> values) const override;
        std::vector<std::string>
        damage_names() const override;
        void
        damages(ConstStateView            state,
                dealii::ArrayView<double> values) const override;
        /** The units' (the model prints the mortar's on its own). */
        std::vector<DerivedValue>
        derived_values() const override;

        bool
        is_linear() const override;
        /** Whether each nonlinear part extrapolates. */
        bool
        extrapolates() const override;
        /** The units' moduli (scales of the model). */
        double
        youngs_modulus() const override;
        double
        poissons_ratio() const override;
        void
        evaluate(const dealii::SymmetricTensor<2, 3> &strain,
                 ConstStateView                       old,
                 const BrickPoint                    &point,
                 StateView                            updated,
                 dealii::SymmetricTensor<2, 3>       &stress,
                 dealii::SymmetricTensor<4, 3>       &tangent) const override;
        void
        update_state(const dealii::SymmetricTensor<2, 3> &strain,
                     ConstStateView                       old,
                     const BrickPoint                    &point,
                     StateView                            updated,
                     dealii::SymmetricTensor<2, 3> &stress) const override;
        void
        evaluate_extrapolated(
          const dealii::SymmetricTensor<2, 3> &strain,
          ConstStateView                       old,
          ConstStateView                       older,
          const double                         ratio,
          const BrickPoint                    &point,
          dealii::SymmetricTensor<2, 3>       &stress,
          dealii::SymmetricTensor<4, 3>       &tangent) const override;
        void
        extrapolated_stress(
          const dealii::SymmetricTensor<2, 3> &strain,
          ConstStateView                       old,
          ConstStateView                       older,
          const double                         ratio,
          const BrickPoint                    &point,
          dealii::SymmetricTensor<2, 3>       &stress) const override;
        bool
        is_elastic(const dealii::SymmetricTensor<2, 3> &strain,
                   ConstStateView                       old,
                   const BrickPoint                    &point) const override;
        void
        check_point(const BrickPoint &point) const override;
        dealii::SymmetricTensor<4, 3>
        elastic_stiffness() const override;
        dealii::SymmetricTensor<4, 3>
        elastic_stiffness_at(const BrickPoint &point) const override;
        /** The units' (the mortar's must be 0). */
        double
        nonlocal_length() const override;
        std::array<double, 2>
        nonlocal_measures(const dealii::SymmetricTensor<2, 3> &strain,
                          ConstStateView                       old,
                          const BrickPoint &point) const override;
        /** The units' strengths (the splitting interfaces). */
        double
        compressive_strength() const override;
        double
        tensile_strength() const override;
        double
        tensile_fracture_energy() const override;

      private:
        /** The law of @p region and the offset and size of its part of a
         * point's state. */
        struct Part
        {
          const BrickMaterial *law;
          unsigned int         offset, size;
        };
        Part
        part(const unsigned int region) const;

        const BrickMaterial &unit, &mortar;
        /** Doubles of the units' and the mortar's states. */
        unsigned int n_unit = 0, n_mortar = 0;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
