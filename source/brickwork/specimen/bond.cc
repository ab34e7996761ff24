/**
 * @file
 * The bond family: the defaults of Bond.
 */
#include <masonry/brickwork/bond.h>

namespace masonry
{
  namespace brickwork
  {
    const char *
    Bond::default_plugin()
    {
      return "stretcher";
    }

    std::string
    Bond::selection_documentation()
    {
      return "The bond pattern of the wallette: how the enlarged bricks "
             "(brick plus half a joint on every side) are laid. x runs along "
             "the wall, y across it, z up; the wallette stands on z = 0.";
    }



  } // namespace brickwork
} // namespace masonry
