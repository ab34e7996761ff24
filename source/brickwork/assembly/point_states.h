/**
 * @file
 * The states of the integration points of one law, in flat arrays: the
 * converged state (old), the one being computed (updated) and the one a step
 * further back (older, for IMPL-EX). The layout of a point's state is what
 * its law declares (state_variables()); nothing here knows a variable.
 */
#ifndef masonry_brickwork_model_point_states_h
#define masonry_brickwork_model_point_states_h

#include <masonry/brickwork/state.h>

#include <vector>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Old, updated and older states of a set of points. */
      class PointStates
      {
      public:
        /**
         * @p n_points points of @p n_values doubles each, all starting from
         * @p initial (n_values doubles); @p checkpointed: the points this
         * rank writes to (and reads from) checkpoints.
         */
        void
        initialize(const unsigned int               n_points,
                   const std::vector<double>       &initial,
                   const std::vector<unsigned int> &checkpointed);

        /** Number of points. */
        unsigned int
        n_points() const
        {
          return count;
        }

        /** Doubles per point. */
        unsigned int
        n_values() const
        {
          return n;
        }

        ConstStateView
        old(const unsigned int p) const
        {
          return {old_values.data() + p * n, n};
        }
        ConstStateView
        older(const unsigned int p) const
        {
          return {older_values.data() + p * n, n};
        }
        ConstStateView
        updated(const unsigned int p) const
        {
          return {new_values.data() + p * n, n};
        }
        StateView
        updated(const unsigned int p)
        {
          return {new_values.data() + p * n, n};
        }

        /** The state of point @p p that freeze() kept. */
        ConstStateView
        frozen(const unsigned int p) const
        {
          return {frozen_values.data() + p * n, n};
        }

        /** Keep every point's updated state (frozen()). */
        void
        freeze()
        {
          frozen_values = new_values;
        }

        /** The largest difference between a damage of @p law in the
         * updated and the frozen state over this rank's points
         * (checkpointed ones; NaN if one is not finite). */
        double
        largest_damage_change(const PointLaw &law) const;

        /** The point's updated state is its converged one (no change). */
        void
        keep(const unsigned int p);

        /** The updated state of point @p p becomes the converged one; with
         * @p keep_older the converged one becomes the older one first. */
        void
        accept(const unsigned int p, const bool keep_older);

        /** Write or read the old and older states of the checkpointed
         * points (on reading, updated = old). */
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          std::vector<double> data;
          if (Archive::is_saving::value)
            data = gather();
          ar &data;
          if (Archive::is_loading::value)
            scatter(data);
        }

      private:
        std::vector<double>
        gather() const;
        void
        scatter(const std::vector<double> &data);

        unsigned int        n = 0, count = 0;
        std::vector<double> old_values, new_values, older_values, frozen_values;
        std::vector<unsigned int> checkpointed;
      };

      /** The point states of the laws of a LawSet, indexed as its laws:
       * brick points by cell region (8 c + q: every region's states hold
       * every cell's points, a cell uses those of its region), joint points
       * by slot (4 n + q: every slot's states hold every face's points, a
       * face uses those of its type's slot). */
      struct LawStates
      {
        std::vector<PointStates> bricks, joints;

        /** Write or read every law's states (PointStates::serialize()). */
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          for (PointStates &s : bricks)
            ar &s;
          for (PointStates &s : joints)
            ar &s;
        }
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
