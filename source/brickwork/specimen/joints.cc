/**
 * @file
 * Joint detection: coincident face pairs.
 */
#include <deal.II/base/exceptions.h>

#include "joints.h"

#include <cmath>
#include <map>
#include <set>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      const char *joint_type_name[4] = {"bed", "head", "collar", "splitting"};

      Joints
      find_joints(const DoFHandler<3> &dof_handler, const double height)
      {
        Joints joints;
        // distinct face centres are at least a fraction of the smallest
        // cell apart, coincident ones within rounding: a lexicographic
        // order with a tolerance far below the one and above the other is
        // a strict weak order on them (the detailed model's grid is not
        // uniform, so the centres lie on no common grid)
        const double tol  = 1e-9 * height;
        const auto   less = [tol](const Point<3> &a, const Point<3> &b) {
          for (unsigned int d = 0; d < 3; ++d)
            if (a[d] < b[d] - tol)
              return true;
            else if (a[d] > b[d] + tol)
              return false;
          return false;
        };
        std::map<Point<3>,
                 std::pair<DoFHandler<3>::active_cell_iterator, unsigned int>,
                 decltype(less)>
                                                        open(less);
        std::set<std::pair<unsigned int, unsigned int>> pairs[4];
        auto key = [](const Point<3> &p) { return p; };
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<3>     c    = cell->face(f)->center();
                const unsigned int axis = f / 2;
                // the platens
                if (axis == 2 &&
                    (std::abs(c[2]) < tol || std::abs(c[2] - height) < tol))
                  continue;
                const auto k  = key(c);
                const auto it = open.find(k);
                if (it == open.end())
                  {
                    open.emplace(k, std::make_pair(cell, f));
                    continue;
                  }
                auto         other = it->second;
                auto         a = other.first, b = cell;
                unsigned int fa = other.second, fb = f;
                if (a->center()[axis] > b->center()[axis])
                  {
                    std::swap(a, b);
                    std::swap(fa, fb);
                  }
                open.erase(it);
                InterfaceFace face;
                face.axis  = axis;
                face.type  = axis == 2 ? 0 : axis == 0 ? 1 : 2;
                face.owned = a->is_locally_owned();
                face.dofs.resize(24);
                face.brick_a = a->material_id();
                face.brick_b = b->material_id();
                // the two halves of a split unit
                if (face.brick_a == face.brick_b)
                  face.type = splitting_type;
                face.cell_a = a->active_cell_index();
                face.cell_b = b->active_cell_index();
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    face.vertices[v] = a->face(fa)->vertex(v);
                    unsigned int w   = 4;
                    for (unsigned int x = 0; x < 4; ++x)
                      if (a->face(fa)->vertex(v).distance(
                            b->face(fb)->vertex(x)) < tol)
                        w = x;
                    AssertThrow(w < 4,
                                ExcMessage("internal error: a joint's faces "
                                           "do not coincide"));
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        face.dofs[3 * v + d] =
                          a->face(fa)->vertex_dof_index(v, d);
                        face.dofs[12 + 3 * v + d] =
                          b->face(fb)->vertex_dof_index(w, d);
                      }
                  }
                face.area =
                  cross_product_3d(face.vertices[1] - face.vertices[0],
                                   face.vertices[2] - face.vertices[0])
                    .norm();
                ++joints.n_faces_of_type[face.type];
                pairs[face.type].insert({face.brick_a, face.brick_b});
                joints.faces.push_back(face);
              }
        for (unsigned int t = 0; t < 4; ++t)
          joints.n_joints_of_type[t] = pairs[t].size();
        return joints;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
