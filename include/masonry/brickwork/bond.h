/**
 * @file
 * Bond patterns of brickwork (`subsection Bond`, `set Pattern = ...`): where
 * the enlarged bricks (brick plus half a joint all round) of a wallette lie.
 */
#ifndef masonry_brickwork_bond_h
#define masonry_brickwork_bond_h

#include <masonry/core/plugins.h>

#include <array>
#include <string>
#include <vector>

namespace masonry
{
  /** Mesoscale models of bonded brickwork. */
  namespace brickwork
  {
    /** An axis-aligned enlarged brick (m): x along the wall, y across, z
     * up. */
    struct Box
    {
      std::array<double, 3> lower;
      std::array<double, 3> upper;
      /** "stretcher", "header", "closer" (queen closer) or "half bat". */
      std::string kind;
    };

    /** Sizes of the enlarged unit and of the wallette. */
    struct WalletteSize
    {
      /** Enlarged brick length, width, height (brick + joint), m. */
      double length = 0.225, width = 0.1125, height = 0.075;
      /** Number of courses. */
      unsigned int courses = 5;
      /** Length of the wallette in brick lengths. */
      unsigned int bricks_long = 2;
    };

    /**
     * Base class of bond patterns: the layout of the enlarged bricks of a
     * wallette that stands on z = 0 with its face on y = 0 and its end on
     * x = 0.
     */
    class Bond : public plugins::InterfaceBase
    {
    public:
      /** Parameters live in `subsection Bond`. */
      static constexpr const char *registry_section = "Bond";
      /** The selection entry: `set Pattern = ...`. */
      static constexpr const char *registry_entry = "Pattern";
      /** Default selection: "stretcher". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();


      /** The enlarged bricks of a wallette of size @p size. */
      virtual std::vector<Box>
      layout(const WalletteSize &size) const = 0;
    };
  } // namespace brickwork
} // namespace masonry

/** Register a bond pattern (one line in its .cc file). */
#define MASONRY_REGISTER_BOND(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::Bond,         \
                          classname,                        \
                          name,                             \
                          description)

#endif
