/**
 * @file
 * Helpers of the local-refinement tests of the block model.
 */
#ifndef masonry_tests_local_refinement_common_h
#define masonry_tests_local_refinement_common_h

#include <masonry/rigid_blocks/block_model.h>

#include <cmath>
#include <utility>

namespace test
{
  /** Whether every contact point of @p a is one of @p b's (position,
   * normal up to the sign, area) and both have as many. */
  inline bool
  same_points(const masonry::rigid_blocks::Interface &a,
              const masonry::rigid_blocks::Interface &b)
  {
    if (a.points.size() != b.points.size())
      return false;
    for (const auto &p : a.points)
      {
        bool found = false;
        for (const auto &q : b.points)
          found =
            found || (p.position.distance(q.position) < 1e-10 &&
                      std::abs(std::abs(p.normal * q.normal) - 1) < 1e-12 &&
                      std::abs(p.area - q.area) < 1e-12 * q.area);
        if (!found)
          return false;
      }
    return true;
  }

  /** The meshes of the barrel vault compared: 2 x 2 blocks per half (to be
   * split) and the uniform 4 x 4, both supported on the springings. */
  inline std::pair<masonry::rigid_blocks::Discretisation,
                   masonry::rigid_blocks::Discretisation>
  coarse_and_fine()
  {
    masonry::rigid_blocks::Discretisation coarse;
    coarse.n_u             = 2;
    coarse.n_v             = 2;
    coarse.supported_edges = {"springing left", "springing right"};
    masonry::rigid_blocks::Discretisation fine = coarse;
    fine.n_u = fine.n_v = 4;
    return {coarse, fine};
  }
} // namespace test

#endif
