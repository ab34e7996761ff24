/**
 * @file
 * The laws of a wallette, keyed by what they act on: one brick material per
 * cell region (the units; the mortar of the detailed model) and one
 * interface law per joint type (bed, head, collar; the splitting interfaces
 * through the units). Each distinct law has its own point states (the
 * layout it declares), so a law never carries another's variables; the
 * joint types that share a law (bed, head and collar share `Interface
 * law') share its states. Public: a postprocessor reads the run's through
 * ModelView::laws (the driver builds it and hands it to the model).
 */
#ifndef masonry_brickwork_law_set_h
#define masonry_brickwork_law_set_h

#include <array>
#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    class BrickMaterial;
    class InterfaceLaw;

    /** The cell regions (ModelView::cell_region(), Specimen::cell_region):
     * the key of a cell's law in a LawSet. */
    constexpr unsigned int unit_region = 0, mortar_region = 1;

    /** A law of a LawSet and how the run names it. */
    template <class Law>
    struct LawEntry
    {
      const Law *law = nullptr;
      /** The parameter entry that selects the law, as an error names it
       * (e.g. `Brick material/Model'). */
      std::string entry;
      /** The prefix of its variables' names in the outputs ("" for the
       * units and the joints, "mortar_", "splitting_"). */
      std::string prefix;
    };

    /** The laws of the cell regions and of the joint types. */
    class LawSet
    {
    public:
      /** The law of the next cell region (the first call: the units). */
      void
      add_region_law(const BrickMaterial &law,
                     const std::string   &entry,
                     const std::string   &prefix);
      /** @p law for the joint faces of every type in @p types (one set of
       * point states for them all); a type has at most one law. */
      void
      add_joint_law(const std::vector<unsigned int> &types,
                    const InterfaceLaw              &law,
                    const std::string               &entry,
                    const std::string               &prefix);

      /** @name The cell regions */
      /** @{ */
      /** Number of regions with a law (1, or 2 in the detailed model). */
      unsigned int
      n_regions() const
      {
        return regions.size();
      }
      const LawEntry<BrickMaterial> &
      region(const unsigned int r) const
      {
        return regions.at(r);
      }
      /** The law of the cells of region @p r. */
      const BrickMaterial &
      brick_law(const unsigned int r) const
      {
        return *regions.at(r).law;
      }
      /** Whether every region's law is linear (the bricks have no point
       * states and keep their elastic matrices). */
      bool
      bricks_linear() const;
      /** The damage variables of every region's law, each with its
       * region's prefix, in the order of the regions (the brick damages
       * of curve.csv). */
      std::vector<std::string>
      brick_damage_names() const;
      /** Where region @p r's damages start in brick_damage_names(). */
      unsigned int
      first_brick_damage(const unsigned int r) const;
      /** @} */

      /** @name The joint types */
      /** @{ */
      /** Number of distinct joint laws (each with its point states). */
      unsigned int
      n_joint_laws() const
      {
        return joints.size();
      }
      const LawEntry<InterfaceLaw> &
      joint(const unsigned int slot) const
      {
        return joints.at(slot);
      }
      /** The slot (index of joint()) of the law of joint type @p type
       * (InterfaceFace::type); an error if it has none. */
      unsigned int
      slot_of_type(const unsigned int type) const;
      /** Whether joint type @p type has a law. */
      bool
      has_joint_law(const unsigned int type) const;
      /** The law of the faces of type @p type. */
      const InterfaceLaw &
      joint_law(const unsigned int type) const
      {
        return *joints[slot_of_type(type)].law;
      }
      /** Whether every joint law is linear. */
      bool
      joints_linear() const;
      /** @} */

    private:
      std::vector<LawEntry<BrickMaterial>> regions;
      std::vector<LawEntry<InterfaceLaw>>  joints;
      /** The slot of each joint type (bed, head, collar, splitting);
       * no_slot: none. */
      static constexpr unsigned int no_slot = ~0u;
      std::array<unsigned int, 4>   slots{{no_slot, no_slot, no_slot, no_slot}};
    };
  } // namespace brickwork
} // namespace masonry

#endif
