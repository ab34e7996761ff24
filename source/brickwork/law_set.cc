/**
 * @file
 * The laws of the cell regions and the joint types.
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/law_set.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>

namespace masonry
{
  namespace brickwork
  {
    void
    LawSet::add_region_law(const BrickMaterial &law,
                           const std::string   &entry,
                           const std::string   &prefix)
    {
      regions.push_back({&law, entry, prefix});
    }

    void
    LawSet::add_joint_law(const std::vector<unsigned int> &types,
                          const InterfaceLaw              &law,
                          const std::string               &entry,
                          const std::string               &prefix)
    {
      for (const unsigned int t : types)
        {
          AssertThrow(t < slots.size() && slots[t] == no_slot,
                      dealii::ExcMessage(
                        "internal error: a joint type without a law of its "
                        "own or with two laws (" +
                        entry + ")"));
          slots[t] = joints.size();
        }
      joints.push_back({&law, entry, prefix});
    }

    bool
    LawSet::bricks_linear() const
    {
      return std::all_of(regions.begin(), regions.end(), [](const auto &r) {
        return r.law->is_linear();
      });
    }

    std::vector<std::string>
    LawSet::brick_damage_names() const
    {
      std::vector<std::string> names;
      for (const auto &r : regions)
        for (const auto &name : r.law->damage_names())
          names.push_back(r.prefix + name);
      return names;
    }

    unsigned int
    LawSet::first_brick_damage(const unsigned int r) const
    {
      unsigned int first = 0;
      for (unsigned int k = 0; k < r; ++k)
        first += regions.at(k).law->damage_names().size();
      return first;
    }

    unsigned int
    LawSet::slot_of_type(const unsigned int type) const
    {
      AssertThrow(has_joint_law(type),
                  dealii::ExcMessage(
                    "the wallette has no law for joint type " +
                    std::to_string(type) +
                    " (0 bed, 1 head, 2 collar, 3 splitting: the splitting "
                    "interfaces need `Splitting interfaces = true')"));
      return slots[type];
    }

    bool
    LawSet::has_joint_law(const unsigned int type) const
    {
      return type < slots.size() && slots[type] != no_slot;
    }

    bool
    LawSet::joints_linear() const
    {
      return std::all_of(joints.begin(), joints.end(), [](const auto &j) {
        return j.law->is_linear();
      });
    }
  } // namespace brickwork
} // namespace masonry
