// Local (non-conforming) refinement of a block mesh
// (rigid_blocks::Discretisation::splits), against the uniform mesh built by
// the conforming code path: the Bothwell barrel vault (two patches glued at
// the crown) at 2 x 2 blocks per half with two blocks of the first patch
// split into four, one next to the crown and one next to the springing
// (diagonally apart). Where a split block meets an unsplit one, the edge
// carries one interface per small block along the common half of the edge
// (a T-junction, also across the crown and on the support). The geometry
// of every interface of a small block then coincides with that of the
// uniform 4 x 4 mesh, so its contact points must be the same points, with
// the same normals (up to the orientation) and tributary areas (1e-12);
// two split blocks of 2 x 2 with a free edge each (the vault's ends carry
// no interface) have 2 x (4 + 3 x 2) = 20 such interfaces, 10 of them
// T-junctions (2 across the crown: the two halves of the pointed vault meet
// at an angle there, and the contact points take the geometry of the first
// patch, as on the conforming mesh) and 2 on the support.

#include <masonry/rigid_blocks/block_model.h>

#include "geometry_common.h"
#include "local_refinement_common.h"

using namespace masonry;

int
main()
{
  const auto vault    = test::create("barrel vault", "");
  auto [coarse, fine] = test::coarse_and_fine();
  coarse.splits       = {
          {{dealii::Point<2>(0.25, 0.25), dealii::Point<2>(0.75, 0.75)}}, {}};
  const rigid_blocks::BlockModel local(*vault, coarse), uniform(*vault, fine);

  const auto &blocks = local.blocks();
  test::check(blocks.size() == 2 * 4 + 2 * 3,
              "two of eight blocks split into four: 14 blocks");
  // a small block spans a quarter of the parameter square along u
  auto small = [&](const unsigned int b) {
    const auto &c = blocks[b].corners;
    return b != rigid_blocks::Interface::support &&
           std::abs(c[1][0] - c[0][0]) < 0.3;
  };
  unsigned int n = 0, matched = 0, t_junctions = 0, across = 0, support = 0;
  for (const auto &i : local.interfaces())
    {
      if (!small(i.first) && !small(i.second))
        continue;
      ++n;
      const bool t = i.second != rigid_blocks::Interface::support &&
                     small(i.first) != small(i.second);
      t_junctions += t;
      across += t && blocks[i.first].patch != blocks[i.second].patch;
      support += i.second == rigid_blocks::Interface::support;
      for (const auto &j : uniform.interfaces())
        if (test::same_points(i, j))
          {
            ++matched;
            break;
          }
    }
  test::check(n == 20, "20 interfaces of the small blocks");
  test::check(t_junctions == 10 && across == 2 && support == 2,
              "10 of them along half an edge of a large block (2 across the "
              "crown), 2 on the support");
  test::check(matched == n,
              "every one has the contact points of the uniform 4 x 4 mesh "
              "(1e-12)");
  std::cout << "interfaces of small blocks " << n << ", matched " << matched
            << ", T-junctions " << t_junctions << " (" << across
            << " across the crown), on the support " << support << "\n";
  return test::failures();
}
