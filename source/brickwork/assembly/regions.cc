/**
 * @file
 * Units and mortar behind one material.
 */
#include "regions.h"

#include <algorithm>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using dealii::SymmetricTensor;

      namespace
      {
        /** A law's state variables with linear laws' none. */
        std::vector<StateVariable>
        variables(const BrickMaterial &law)
        {
          return law.is_linear() ? std::vector<StateVariable>() :
                                   law.state_variables();
        }

        std::vector<std::string>
        prefixed(std::vector<std::string> names)
        {
          for (auto &n : names)
            n = "mortar_" + n;
          return names;
        }

        ConstStateView
        slice(ConstStateView v, const unsigned int offset, const unsigned n)
        {
          return {v.data() + offset, n};
        }

        StateView
        slice(StateView v, const unsigned int offset, const unsigned n)
        {
          return {v.data() + offset, n};
        }
      } // namespace

      RegionMaterial::RegionMaterial(const BrickMaterial &unit,
                                     const BrickMaterial &mortar)
        : unit(unit)
        , mortar(mortar)
        , n_unit(n_state_values(variables(unit)))
        , n_mortar(n_state_values(variables(mortar)))
      {
        AssertThrow(mortar.nonlocal_length() == 0,
                    dealii::ExcMessage(
                      "Mortar material: `Nonlocal length' must be 0 (the "
                      "nonlocal average acts on the units only)"));
      }

      double
      RegionMaterial::nonlocal_length() const
      {
        return unit.nonlocal_length();
      }

      std::array<double, 2>
      RegionMaterial::nonlocal_measures(const SymmetricTensor<2, 3> &strain,
                                        ConstStateView               old,
                                        const BrickPoint &point) const
      {
        const Part p = part(point.region);
        return p.law->nonlocal_measures(strain,
                                        slice(old, p.offset, p.size),
                                        point);
      }

      RegionMaterial::Part
      RegionMaterial::part(const unsigned int region) const
      {
        return region == mortar_region ? Part{&mortar, n_unit, n_mortar} :
                                         Part{&unit, 0, n_unit};
      }

      std::vector<StateVariable>
      RegionMaterial::state_variables() const
      {
        auto v = variables(unit);
        for (auto m : variables(mortar))
          {
            m.name = "mortar_" + m.name;
            v.push_back(m);
          }
        return v;
      }

      void
      RegionMaterial::initial_state(StateView state) const
      {
        if (n_unit > 0)
          unit.initial_state(slice(state, 0, n_unit));
        if (n_mortar > 0)
          mortar.initial_state(slice(state, n_unit, n_mortar));
      }

      std::vector<std::string>
      RegionMaterial::reported_quantities() const
      {
        std::vector<std::string> names;
        if (!unit.is_linear())
          names = unit.reported_quantities();
        if (!mortar.is_linear())
          for (const auto &n : prefixed(mortar.reported_quantities()))
            names.push_back(n);
        return names;
      }

      void
      RegionMaterial::report(ConstStateView            state,
                             dealii::ArrayView<double> values) const
      {
        unsigned int k = 0;
        if (!unit.is_linear())
          {
            k = unit.reported_quantities().size();
            unit.report(slice(state, 0, n_unit), {values.data(), k});
          }
        if (!mortar.is_linear())
          mortar.report(slice(state, n_unit, n_mortar),
                        {values.data() + k, values.size() - k});
      }

      std::vector<std::string>
      RegionMaterial::damage_names() const
      {
        auto names = unit.damage_names();
        for (const auto &n : prefixed(mortar.damage_names()))
          names.push_back(n);
        return names;
      }

      void
      RegionMaterial::damages(ConstStateView            state,
                              dealii::ArrayView<double> values) const
      {
        const unsigned int k = unit.damage_names().size();
        unit.damages(slice(state, 0, n_unit), {values.data(), k});
        mortar.damages(slice(state, n_unit, n_mortar),
                       {values.data() + k, values.size() - k});
      }

      std::vector<DerivedValue>
      RegionMaterial::derived_values() const
      {
        return unit.derived_values();
      }

      bool
      RegionMaterial::is_linear() const
      {
        return unit.is_linear() && mortar.is_linear();
      }

      bool
      RegionMaterial::extrapolates() const
      {
        return (unit.is_linear() || unit.extrapolates()) &&
               (mortar.is_linear() || mortar.extrapolates());
      }

      double
      RegionMaterial::youngs_modulus() const
      {
        return unit.youngs_modulus();
      }

      double
      RegionMaterial::poissons_ratio() const
      {
        return unit.poissons_ratio();
      }

      void
      RegionMaterial::evaluate(const SymmetricTensor<2, 3> &strain,
                               ConstStateView               old,
                               const BrickPoint            &point,
                               StateView                    updated,
                               SymmetricTensor<2, 3>       &stress,
                               SymmetricTensor<4, 3>       &tangent) const
      {
        const Part p = part(point.region);
        // the other region's part stays as it was
        std::copy(old.begin(), old.end(), updated.begin());
        p.law->evaluate(strain,
                        slice(old, p.offset, p.size),
                        point,
                        slice(updated, p.offset, p.size),
                        stress,
                        tangent);
      }

      void
      RegionMaterial::update_state(const SymmetricTensor<2, 3> &strain,
                                   ConstStateView               old,
                                   const BrickPoint            &point,
                                   StateView                    updated,
                                   SymmetricTensor<2, 3>       &stress) const
      {
        const Part p = part(point.region);
        std::copy(old.begin(), old.end(), updated.begin());
        p.law->update_state(strain,
                            slice(old, p.offset, p.size),
                            point,
                            slice(updated, p.offset, p.size),
                            stress);
      }

      void
      RegionMaterial::evaluate_extrapolated(
        const SymmetricTensor<2, 3> &strain,
        ConstStateView               old,
        ConstStateView               older,
        const double                 ratio,
        const BrickPoint            &point,
        SymmetricTensor<2, 3>       &stress,
        SymmetricTensor<4, 3>       &tangent) const
      {
        const Part p = part(point.region);
        p.law->evaluate_extrapolated(strain,
                                     slice(old, p.offset, p.size),
                                     slice(older, p.offset, p.size),
                                     ratio,
                                     point,
                                     stress,
                                     tangent);
      }

      void
      RegionMaterial::extrapolated_stress(const SymmetricTensor<2, 3> &strain,
                                          ConstStateView               old,
                                          ConstStateView               older,
                                          const double                 ratio,
                                          const BrickPoint            &point,
                                          SymmetricTensor<2, 3> &stress) const
      {
        const Part p = part(point.region);
        p.law->extrapolated_stress(strain,
                                   slice(old, p.offset, p.size),
                                   slice(older, p.offset, p.size),
                                   ratio,
                                   point,
                                   stress);
      }

      bool
      RegionMaterial::is_elastic(const SymmetricTensor<2, 3> &strain,
                                 ConstStateView               old,
                                 const BrickPoint            &point) const
      {
        const Part p = part(point.region);
        return p.law->is_elastic(strain, slice(old, p.offset, p.size), point);
      }

      void
      RegionMaterial::check_point(const BrickPoint &point) const
      {
        part(point.region).law->check_point(point);
      }

      SymmetricTensor<4, 3>
      RegionMaterial::elastic_stiffness() const
      {
        return unit.elastic_stiffness();
      }

      SymmetricTensor<4, 3>
      RegionMaterial::elastic_stiffness_at(const BrickPoint &point) const
      {
        return part(point.region).law->elastic_stiffness();
      }

      double
      RegionMaterial::compressive_strength() const
      {
        return unit.compressive_strength();
      }

      double
      RegionMaterial::tensile_strength() const
      {
        return unit.tensile_strength();
      }

      double
      RegionMaterial::tensile_fracture_energy() const
      {
        return unit.tensile_fracture_energy();
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
