/**
 * @file
 * The defaults of the joint models of the rigid blocks (`Interface
 * model/Model`); each model is a file of interface_models/.
 */
#include <masonry/rigid_blocks/interface_model.h>

namespace masonry
{
  namespace rigid_blocks
  {
    const char *
    InterfaceModel::default_plugin()
    {
      return "no tension no sliding";
    }

    std::string
    InterfaceModel::selection_documentation()
    {
      return "The strength of the joints between blocks and of the joints "
             "with unilateral supports (bonded supports are rigid). The "
             "tractions are written per contact point, each with its "
             "tributary area: the contact points sit at the intrados and "
             "at the extrados of every station along an interface edge, so "
             "the rule is the trapezoid rule along the edge and across the "
             "thickness. It integrates the dissipation exactly when the "
             "jump is linear across the thickness and of one sign (a hinge "
             "at a face, a sliding or opening joint); with a finite "
             "compressive strength the rotation centre of a crushing joint "
             "lies inside the section, where two points only approximate "
             "the stress block.";
    }



    bool
    InterfaceModel::no_tension_no_sliding() const
    {
      return false;
    }
  } // namespace rigid_blocks
} // namespace masonry
