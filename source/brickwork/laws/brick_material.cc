/**
 * @file
 * The brick material family: the defaults of BrickMaterial.
 */
#include <masonry/brickwork/brick_material.h>

#include <algorithm>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    // ---------------------------------------------------------------------
    const char *
    BrickMaterial::default_plugin()
    {
      return "elastic";
    }

    std::string
    BrickMaterial::selection_documentation()
    {
      return "The constitutive law of the enlarged bricks (brick plus half "
             "a joint).";
    }



    const MaterialStrengths *
    strengths_of(const BrickMaterial &law)
    {
      return dynamic_cast<const MaterialStrengths *>(&law);
    }

    const NonlocalMeasures *
    nonlocal_of(const BrickMaterial &law)
    {
      return dynamic_cast<const NonlocalMeasures *>(&law);
    }

    double
    nonlocal_length(const BrickMaterial &law)
    {
      const NonlocalMeasures *n = nonlocal_of(law);
      return n ? n->nonlocal_length() : 0.;
    }

    dealii::SymmetricTensor<4, 3>
    BrickMaterial::elastic_stiffness() const
    {
      const double E = youngs_modulus(), nu = poissons_ratio();
      const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                   mu     = E / (2 * (1 + nu));
      return lambda *
               dealii::outer_product(dealii::unit_symmetric_tensor<3>(),
                                     dealii::unit_symmetric_tensor<3>()) +
             2 * mu * dealii::identity_tensor<3>();
    }

    void
    BrickMaterial::evaluate(const dealii::SymmetricTensor<2, 3> &strain,
                            ConstStateView                       old,
                            const BrickPoint &,
                            StateView                      updated,
                            dealii::SymmetricTensor<2, 3> &stress,
                            dealii::SymmetricTensor<4, 3> &tangent) const
    {
      tangent = elastic_stiffness();
      stress  = tangent * strain;
      std::copy(old.begin(), old.end(), updated.begin());
    }

    void
    BrickMaterial::extrapolated_stress(
      const dealii::SymmetricTensor<2, 3> &strain,
      ConstStateView                       old,
      ConstStateView                       older,
      const double                         ratio,
      const BrickPoint                    &point,
      dealii::SymmetricTensor<2, 3>       &stress) const
    {
      dealii::SymmetricTensor<4, 3> tangent;
      evaluate_extrapolated(strain, old, older, ratio, point, stress, tangent);
    }

    void
    BrickMaterial::update_state(const dealii::SymmetricTensor<2, 3> &strain,
                                ConstStateView                       old,
                                const BrickPoint                    &point,
                                StateView                            updated,
                                dealii::SymmetricTensor<2, 3> &stress) const
    {
      dealii::SymmetricTensor<4, 3> tangent;
      evaluate(strain, old, point, updated, stress, tangent);
    }

    void
    BrickMaterial::check_point(const BrickPoint &) const
    {}

    bool
    BrickMaterial::extrapolates() const
    {
      return false;
    }

    void
    BrickMaterial::evaluate_extrapolated(
      const dealii::SymmetricTensor<2, 3> &strain,
      ConstStateView                       old,
      ConstStateView,
      const double,
      const BrickPoint              &point,
      dealii::SymmetricTensor<2, 3> &stress,
      dealii::SymmetricTensor<4, 3> &tangent) const
    {
      std::vector<double> scratch(old.size());
      evaluate(strain, old, point, scratch, stress, tangent);
    }

    bool
    BrickMaterial::is_elastic(const dealii::SymmetricTensor<2, 3> &,
                              ConstStateView,
                              const BrickPoint &) const
    {
      return is_linear();
    }

  } // namespace brickwork
} // namespace masonry
