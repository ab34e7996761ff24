// The cross-patch T-junction search of a locally refined block mesh
// (rigid_blocks::Discretisation::splits) must cost what the mesh needs, not
// what the number of refinement rounds allows. It once searched every face
// in 2^R pieces for R rounds (`Stages' of the crack refinement), empty rounds
// included: 24 rounds took hours, and from 32 on the piece count `1u << R'
// was undefined. Two meshes of the Bothwell barrel vault (two patches glued
// at the crown), both padded to 24 rounds with empty ones:
// - the two split blocks of tests/rigid_blocks_local_refinement (one next to
//   the crown, one next to the springing): the 20 interfaces of the small
//   blocks must have the contact points of the uniform 4 x 4 mesh (1e-12);
// - a block at a corner of the first patch split 8 times over towards that
//   corner (graded: along the crown the first patch has blocks of 8 sizes
//   against the second's unsplit ones): the crown is a straight line of
//   constant thickness, where the trapezoidal stations are exact, so the
//   interfaces across it must have the area of the uniform 2 x 2 mesh's
//   (1e-12): every small face along the crown is glued to a large one; one
//   interface per small face along the crown: two of the smallest size, one
//   of each other size, and the unsplit block's (8 + 2).
// ctest stops the test after 60 s.

#include <masonry/rigid_blocks/block_model.h>

#include "geometry_common.h"
#include "local_refinement_common.h"

using namespace masonry;

namespace
{
  /** Area of the interfaces between blocks of different patches. */
  double
  crown_area(const rigid_blocks::BlockModel &model, unsigned int &n)
  {
    double area = 0;
    n           = 0;
    for (const auto &i : model.interfaces())
      if (i.second != rigid_blocks::Interface::support &&
          model.blocks()[i.first].patch != model.blocks()[i.second].patch)
        {
          area += i.area;
          ++n;
        }
    return area;
  }
} // namespace

int
main()
{
  const unsigned int rounds = 24;
  const auto         vault  = test::create("barrel vault", "");
  auto [coarse, fine]       = test::coarse_and_fine();

  rigid_blocks::Discretisation two = coarse;
  two.splits.assign(2, std::vector<std::vector<dealii::Point<2>>>(rounds));
  two.splits[0][0] = {dealii::Point<2>(0.25, 0.25),
                      dealii::Point<2>(0.75, 0.75)};
  const rigid_blocks::BlockModel local(*vault, two), uniform(*vault, fine);
  const auto                    &blocks = local.blocks();
  const auto                     small  = [&](const unsigned int b) {
    const auto &c = blocks[b].corners;
    return b != rigid_blocks::Interface::support &&
           std::abs(c[1][0] - c[0][0]) < 0.3;
  };
  unsigned int n = 0, matched = 0;
  for (const auto &i : local.interfaces())
    if (small(i.first) || small(i.second))
      {
        ++n;
        for (const auto &j : uniform.interfaces())
          if (test::same_points(i, j))
            {
              ++matched;
              break;
            }
      }
  test::check(blocks.size() == 14 && n == 20 && matched == n,
              "two blocks split in the first of 24 rounds: 14 blocks, the "
              "20 interfaces of the small blocks those of the uniform 4 x 4 "
              "mesh (1e-12)");

  // a corner of the first patch on the crown: the one whose split block
  // has an interface across the crown
  rigid_blocks::Discretisation deep = coarse;
  deep.splits.assign(2, std::vector<std::vector<dealii::Point<2>>>(rounds));
  const unsigned int levels = 8;
  unsigned int       n_crown_uniform;
  const double       uniform_area =
    crown_area(rigid_blocks::BlockModel(*vault, coarse), n_crown_uniform);
  bool found = false;
  for (const double cu : {0., 1.})
    for (const double cv : {0., 1.})
      {
        for (unsigned int r = 0; r < levels; ++r)
          {
            // the cell at the corner (cu, cv) of side 2^-(r + 1)
            const double h    = std::ldexp(1., -int(r) - 2);
            deep.splits[0][r] = {
              dealii::Point<2>(cu == 0 ? h : 1 - h, cv == 0 ? h : 1 - h)};
          }
        const rigid_blocks::BlockModel model(*vault, deep);
        unsigned int                   n_crown;
        const double                   area = crown_area(model, n_crown);
        if (n_crown <= n_crown_uniform)
          continue;
        found = true;
        // along the crown, the first patch's blocks (graded): two of the
        // last level, one of every other level, the unsplit one of 2 x 2
        test::check(n_crown == levels + 2 &&
                      std::abs(area - uniform_area) < 1e-12 * uniform_area,
                    "a corner block on the crown split 8 times over: 10 "
                    "interfaces across the crown with the uniform mesh's "
                    "area (1e-12)");
        std::cout << "across the crown: " << n_crown << " interfaces (uniform "
                  << n_crown_uniform << "), relative area difference "
                  << (std::abs(area - uniform_area) < 1e-12 * uniform_area ?
                        "below 1e-12" :
                        "above 1e-12")
                  << "\n";
      }
  test::check(found, "one corner of the first patch is on the crown");
  return test::failures();
}
