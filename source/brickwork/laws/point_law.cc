/**
 * @file
 * What every point law (brick material, interface law) shares: the
 * layout of its state and the defaults of PointLaw.
 */
#include <masonry/brickwork/state.h>

#include <algorithm>
#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    unsigned int
    n_state_values(const std::vector<StateVariable> &variables)
    {
      unsigned int n = 0;
      for (const auto &v : variables)
        n += v.n_components;
      return n;
    }

    std::vector<std::string>
    component_names(const std::vector<StateVariable> &variables)
    {
      std::vector<std::string> names;
      for (const auto &v : variables)
        if (v.n_components == 1)
          names.push_back(v.name);
        else
          for (unsigned int c = 0; c < v.n_components; ++c)
            names.push_back(v.name + "_" + std::to_string(c));
      return names;
    }

    namespace
    {
      void
      copy_state(ConstStateView state, dealii::ArrayView<double> values)
      {
        AssertDimension(state.size(), values.size());
        std::copy(state.begin(), state.end(), values.begin());
      }
    } // namespace

    std::vector<StateVariable>
    PointLaw::state_variables() const
    {
      return {};
    }

    void
    PointLaw::initial_state(StateView state) const
    {
      std::fill(state.begin(), state.end(), 0.);
    }

    std::vector<std::string>
    PointLaw::reported_quantities() const
    {
      return component_names(state_variables());
    }

    void
    PointLaw::report(ConstStateView            state,
                     dealii::ArrayView<double> values) const
    {
      copy_state(state, values);
    }

    std::vector<std::string>
    PointLaw::damage_names() const
    {
      return {};
    }

    void
    PointLaw::damages(ConstStateView, dealii::ArrayView<double>) const
    {}

    std::vector<DerivedValue>
    PointLaw::derived_values() const
    {
      return {};
    }
  } // namespace brickwork
} // namespace masonry
