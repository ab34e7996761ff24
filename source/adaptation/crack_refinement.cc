/**
 * @file
 * `set Optimiser = crack refinement`: refinement of the block mesh where the
 * mechanism of the current mesh cracks (see CrackRefinement and
 * analysis::RigidBlockAnalysis::refine_at_cracks()).
 */
#include <masonry/adaptation/crack_refinement.h>
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/json.h>
#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>

namespace masonry
{
  namespace adaptation
  {
    void
    CrackRefinement::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Stages",
                        "3",
                        dealii::Patterns::Integer(0, 64),
                        "Refinement stages (dimensionless): each solves the "
                        "current mesh and refines it where it cracks most "
                        "(`Split'); the last mesh is then analysed as usual "
                        "(Stages + 1 LP solves in all). The first mesh is "
                        "the uniform one of `Blocks along u' x `Blocks "
                        "along v'.");
      prm.declare_entry(
        "Split",
        "lines",
        dealii::Patterns::Selection("lines|blocks"),
        "What a stage refines (unitless choice). `lines': whole strips "
        "between neighbouring parameter lines (a tensor-product mesh, "
        "`Marked fraction' and `Marking' below). `blocks': only the blocks "
        "next to cracks, each into four at the middle of its parameter "
        "cell (local refinement: a block may border two smaller ones "
        "along one edge, and that edge then carries one interface per "
        "smaller block, along their common half; neighbours are split "
        "too where two blocks sharing an edge would differ by more than one "
        "split). A block's activity is half the activity (defined below) "
        "of each interface it shares with another block plus all of that "
        "of its support interfaces; the blocks of largest activity whose "
        "activities add up to `Marked fraction' of the total are split "
        "(`Marking' is not used).");
      prm.declare_entry(
        "Marked fraction",
        "0.5",
        dealii::Patterns::Double(0, 1),
        "Dörfler marking (dimensionless, 0 to 1): of all strips of both "
        "directions (between neighbouring lines u = const of a patch, or v "
        "= const), those of largest crack activity whose activities add up "
        "to this fraction of the total are split. An interface's activity "
        "is Σ over its contact points of tributary area × |jump| (m³), its "
        "variation Σ area × |jump − mean jump of its intrados or extrados "
        "points|; an interface on a line u = const adds its activity to "
        "the u strips of its blocks and its variation to their v strips "
        "(half to each block, all to the block of a support interface), "
        "one on a line v = const the other way round: cracks draw lines of "
        "their own direction, and lines across them where they vary along "
        "their length. 1 splits every strip that cracks at all; 0 only the "
        "most active one. Patches glued along lines v = const share those "
        "lines; every patch gets the same number of "
        "lines u = const (a patch with fewer marked strips splits its next "
        "most active ones).");
      prm.declare_entry(
        "Marking",
        "joint",
        dealii::Patterns::Selection("joint|per direction"),
        "`joint': one Dörfler marking of the strips of both directions "
        "(`Marked fraction' of the total activity); `per direction': one "
        "for the u strips (of all patches) and one for the v strips, each "
        "with `Marked fraction' of its own direction's total, so that both "
        "directions are refined every stage (strips whose activity is below "
        "1e-6 of the total of both directions are never split: a direction "
        "without cracks stays). Unitless choice.");
      prm.declare_entry("Largest number of blocks",
                        "100000",
                        dealii::Patterns::Integer(1),
                        "Refinement stops before a stage whose mesh would "
                        "have more blocks than this (all patches; "
                        "dimensionless; with `Split = blocks' not counting "
                        "the neighbours split to keep the mesh graded).");
    }

    void
    CrackRefinement::parse_parameters(dealii::ParameterHandler &prm)
    {
      stages          = prm.get_integer("Stages");
      marked_fraction = prm.get_double("Marked fraction");
      split_blocks    = prm.get("Split") == "blocks";
      per_direction   = prm.get("Marking") == "per direction";
      max_blocks      = prm.get_integer("Largest number of blocks");
    }

    Result
    CrackRefinement::optimise(const MPI_Comm,
                              const std::vector<Fitness> &,
                              const std::vector<double> &,
                              const std::function<void(const Generation &)> &)
    {
      AssertThrow(false,
                  dealii::ExcMessage("crack refinement is not a gene "
                                     "optimiser (the analysis refines)"));
      return {};
    }

    std::vector<bool>
    CrackRefinement::mark(const std::vector<double> &indicator,
                          const unsigned int         at_least,
                          const double               floor) const
    {
      std::vector<unsigned int> order(indicator.size());
      std::iota(order.begin(), order.end(), 0u);
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int a, const unsigned int b) {
                         return indicator[a] > indicator[b];
                       });
      const double total =
        std::accumulate(indicator.begin(), indicator.end(), 0.);
      std::vector<bool> marked(indicator.size(), false);
      double            sum   = 0;
      unsigned int      count = 0;
      for (const unsigned int k : order)
        {
          // round-off activity (a strip that does not crack) never counts
          const bool active = indicator[k] > std::max(1e-9 * total, floor);
          const bool needed =
            active && (count == 0 || sum < marked_fraction * total);
          if (!needed && count >= at_least)
            break;
          marked[k] = true;
          sum += indicator[k];
          ++count;
        }
      return marked;
    }
  } // namespace adaptation

  namespace analysis
  {
    double
    RigidBlockAnalysis::evaluate_cracks(RunContext &, std::vector<double> &)
    {
      AssertThrow(false,
                  ExcParameter("Optimiser",
                               "`crack refinement' is implemented for the "
                               "settlement analysis only"));
      return 0;
    }

    std::vector<double>
    RigidBlockAnalysis::crack_activity(
      const rigid_blocks::Motion                                     &motion,
      const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                               const std::string &)> &ground)
      const
    {
      const auto         &interfaces = model->interfaces();
      std::vector<double> activity(2 * interfaces.size(), 0.);
      for (unsigned int k = 0; k < interfaces.size(); ++k)
        {
          const auto                       &i = interfaces[k];
          std::vector<dealii::Tensor<1, 3>> jumps;
          // mean jump of the intrados and of the extrados points
          std::array<dealii::Tensor<1, 3>, 2> mean;
          std::array<double, 2>               area = {{0., 0.}};
          for (const auto &c : i.points)
            {
              dealii::Tensor<1, 3> other;
              if (i.second != rigid_blocks::Interface::support)
                other = motion.displacement(*model, i.second, c.position);
              else if (ground)
                other = ground(c.position, i.support_label);
              jumps.push_back(other -
                              motion.displacement(*model, i.first, c.position));
              activity[2 * k] += c.area * jumps.back().norm();
              mean[c.intrados] += c.area * jumps.back();
              area[c.intrados] += c.area;
            }
          for (unsigned int s = 0; s < 2; ++s)
            if (area[s] > 0)
              mean[s] /= area[s];
          for (unsigned int p = 0; p < i.points.size(); ++p)
            activity[2 * k + 1] +=
              i.points[p].area * (jumps[p] - mean[i.points[p].intrados]).norm();
        }
      return activity;
    }

    std::vector<double>
    RigidBlockAnalysis::block_activity(
      const std::vector<double> &activity) const
    {
      const auto         &interfaces = model->interfaces();
      std::vector<double> a(model->blocks().size(), 0.);
      for (unsigned int k = 0; k < interfaces.size(); ++k)
        if (interfaces[k].second == rigid_blocks::Interface::support)
          a[interfaces[k].first] += activity[2 * k];
        else
          {
            a[interfaces[k].first] += 0.5 * activity[2 * k];
            a[interfaces[k].second] += 0.5 * activity[2 * k];
          }
      return a;
    }

    namespace
    {
      /** n + 1 uniform line positions in [0, 1]. */
      std::vector<double>
      uniform_lines(const unsigned int n)
      {
        std::vector<double> x(n + 1);
        for (unsigned int k = 0; k <= n; ++k)
          x[k] = double(k) / n;
        return x;
      }

      /** The lines @p x with the marked strips split at their middle. */
      std::vector<double>
      split(const std::vector<double> &x, const std::vector<bool> &marked)
      {
        std::vector<double> y;
        for (unsigned int k = 0; k + 1 < x.size(); ++k)
          {
            y.push_back(x[k]);
            if (marked[k])
              y.push_back(0.5 * (x[k] + x[k + 1]));
          }
        y.push_back(x.back());
        return y;
      }

      /** The strip of @p x (lines) that contains @p t. */
      unsigned int
      strip(const std::vector<double> &x, const double t)
      {
        const auto k = std::upper_bound(x.begin(), x.end(), t) - x.begin();
        return std::min<long>(std::max<long>(k - 1, 0), x.size() - 2);
      }

      Json
      numbers(const std::vector<double> &x)
      {
        Json a = Json::array();
        for (const double t : x)
          a.push_back(t);
        return a;
      }

      /**
       * `Split = blocks`: the blocks that @p refinement marks by their
       * activities @p activities (block_activity()), their centres added
       * to @p splits as one more round of splits of each of the
       * @p n_patches patches and their number to @p n_split. Returns false,
       * splitting nothing, if none is marked or the split mesh would have
       * more than `Largest number of blocks`.
       */
      bool
      split_marked_blocks(
        const adaptation::CrackRefinement                       &refinement,
        const std::vector<rigid_blocks::Block>                  &blocks,
        const std::vector<double>                               &activities,
        const unsigned int                                       n_patches,
        std::vector<std::vector<std::vector<dealii::Point<2>>>> &splits,
        unsigned int                                            &n_split)
      {
        // the centres of the blocks to split, by patch
        std::vector<std::vector<dealii::Point<2>>> centres(n_patches);
        const auto         marked = refinement.mark(activities);
        const unsigned int n_marked =
          std::count(marked.begin(), marked.end(), true);
        if (n_marked == 0 ||
            blocks.size() + 3 * n_marked > refinement.max_blocks)
          return false;
        for (unsigned int b = 0; b < blocks.size(); ++b)
          if (marked[b])
            {
              dealii::Point<2> c;
              for (const auto &corner : blocks[b].corners)
                c += 0.25 * corner;
              centres[blocks[b].patch].push_back(c);
            }
        splits.resize(n_patches);
        for (unsigned int p = 0; p < n_patches; ++p)
          splits[p].push_back(centres[p]);
        n_split += n_marked;
        return true;
      }

      /**
       * The crack activity of the strips between the lines @p u (per
       * patch) and @p v (shared by the patches) of the mesh of @p blocks
       * (on @p patches), from the activities @p activity of its
       * @p interfaces (crack_activity()): added to @p su (per patch, one per
       * u strip) and @p sv (one per v strip).
       */
      void
      strip_activity(const std::vector<rigid_blocks::Interface> &interfaces,
                     const std::vector<rigid_blocks::Block>     &blocks,
                     const std::vector<geometry::Patch>         &patches,
                     const std::vector<std::vector<double>>     &u,
                     const std::vector<double>                  &v,
                     const std::vector<double>                  &activity,
                     std::vector<std::vector<double>>           &su,
                     std::vector<double>                        &sv)
      {
        // crack activity of the strips: an interface on a line u = const
        // counts for the u strips of its blocks (half each, all of it for
        // a support), one on a line v = const for their v strips
        auto add = [&](const unsigned int      b,
                       const dealii::Point<3> &x,
                       const double            a,
                       const double            var) {
          // the edge of block b nearest to x: 0, 1 at u = const, 2, 3 at
          // v = const (deal.II's numbering of the corners)
          const auto &c = blocks[b].corners;
          const std::array<std::array<unsigned int, 2>, 4> edges = {
            {{{0, 2}}, {{1, 3}}, {{0, 1}}, {{2, 3}}}};
          unsigned int nearest = 0;
          double       d       = std::numeric_limits<double>::max();
          for (unsigned int e = 0; e < 4; ++e)
            {
              const dealii::Point<2> m(0.5 * (c[edges[e][0]] + c[edges[e][1]]));
              const double de = patches[blocks[b].patch].point(m).distance(x);
              if (de < d)
                d = de, nearest = e;
            }
          dealii::Point<2> centre;
          for (const auto &corner : c)
            centre += 0.25 * corner;
          const unsigned int p = blocks[b].patch;
          su[p][strip(u[p], centre[0])] += nearest < 2 ? a : var;
          sv[strip(v, centre[1])] += nearest < 2 ? var : a;
        };
        for (unsigned int k = 0; k < interfaces.size(); ++k)
          {
            const double a = activity[2 * k], var = activity[2 * k + 1];
            if (interfaces[k].second == rigid_blocks::Interface::support)
              add(interfaces[k].first, interfaces[k].centre, a, var);
            else
              {
                add(interfaces[k].first,
                    interfaces[k].centre,
                    0.5 * a,
                    0.5 * var);
                add(interfaces[k].second,
                    interfaces[k].centre,
                    0.5 * a,
                    0.5 * var);
              }
          }
      }

      /**
       * The strips to split: one Dörfler marking by @p refinement of the
       * u strips @p su of all patches (@p n_u per patch) and of the v
       * strips @p sv (or one per direction, `Marking = per direction`),
       * into @p mu (per patch) and @p marked_v. Returns the number of u strips
       * that each patch splits.
       */
      unsigned int
      mark_strips(const adaptation::CrackRefinement      &refinement,
                  const std::vector<std::vector<double>> &su,
                  const std::vector<double>              &sv,
                  const unsigned int                      n_u,
                  std::vector<std::vector<bool>>         &mu,
                  std::vector<bool>                      &marked_v)
      {
        const unsigned int n_patches = su.size();
        // one Dörfler marking of all strips of both directions; then
        // every patch splits as many u strips as the one that marks most
        // (its next most active ones)
        std::vector<double> all;
        for (const auto &x : su)
          all.insert(all.end(), x.begin(), x.end());
        all.insert(all.end(), sv.begin(), sv.end());
        std::vector<bool> marked;
        if (refinement.per_direction)
          {
            // u strips of all patches, then v strips
            const double floor =
              1e-6 * std::accumulate(all.begin(), all.end(), 0.);
            const unsigned int n = n_patches * n_u;
            marked =
              refinement.mark(std::vector<double>(all.begin(), all.begin() + n),
                              0,
                              floor);
            const auto mv = refinement.mark(sv, 0, floor);
            marked.insert(marked.end(), mv.begin(), mv.end());
          }
        else
          marked = refinement.mark(all);
        mu.assign(n_patches, {});
        unsigned int n_mu = 0;
        for (unsigned int p = 0; p < n_patches; ++p)
          {
            mu[p].assign(marked.begin() + p * n_u,
                         marked.begin() + (p + 1) * n_u);
            n_mu = std::max<unsigned int>(
              n_mu, std::count(mu[p].begin(), mu[p].end(), true));
          }
        for (unsigned int p = 0; p < n_patches; ++p)
          while (std::count(mu[p].begin(), mu[p].end(), true) < n_mu)
            {
              unsigned int next = n_u;
              for (unsigned int i = 0; i < n_u; ++i)
                if (!mu[p][i] && (next == n_u || su[p][i] > su[p][next]))
                  next = i;
              mu[p][next] = true;
            }
        marked_v.assign(marked.begin() + n_patches * n_u, marked.end());
        return n_mu;
      }

      /**
       * Stage @p s on @p pcout: its mesh (@p n_blocks blocks, @p n_u x
       * @p n_v per patch, @p locally_refined or not), its fitness @p f
       * and the wall time @p seconds (s) since the first stage began;
       * returns the stage's entry of the summary.
       */
      Json
      report_stage(dealii::ConditionalOStream &pcout,
                   const unsigned int          s,
                   const unsigned int          n_blocks,
                   const unsigned int          n_u,
                   const unsigned int          n_v,
                   const bool                  locally_refined,
                   const double                f,
                   const double                seconds)
      {
        {
          std::ostringstream line;
          line << "  stage " << s << ": " << n_blocks << " blocks (" << n_u
               << " x " << n_v << " per patch"
               << (locally_refined ? ", locally refined" : "") << "), ";
          if (std::isfinite(f))
            line << "best " << std::setprecision(8) << f << ", ";
          else
            line << "no finite fitness, ";
          line << std::setprecision(3) << seconds << " s\n";
          pcout << line.str();
        }
        Json stage              = Json::object();
        stage["blocks"]         = n_blocks;
        stage["blocks_along_u"] = n_u;
        stage["blocks_along_v"] = n_v;
        // (none where the analysis is incompatible or failed: the run
        // stops refining, and the result of the last mesh says why)
        if (std::isfinite(f))
          stage["fitness"] = f;
        stage["seconds"] = seconds;
        return stage;
      }

      /**
       * A stage's mesh, kept to fall back on: the lines u (per patch) and
       * v, the rounds of block splits and their number.
       */
      struct KeptMesh
      {
        std::vector<std::vector<double>>                        u;
        std::vector<double>                                     v;
        std::vector<std::vector<std::vector<dealii::Point<2>>>> splits;
        unsigned int                                            n_split = 0;
      };
    } // namespace

    void
    RigidBlockAnalysis::refine_at_cracks(RunContext &context)
    {
      const auto &refinement =
        dynamic_cast<const adaptation::CrackRefinement &>(*optimiser);
      auto                            &pcout     = context.pcout;
      const unsigned int               n_patches = geometry->patches().size();
      std::vector<std::vector<double>> u(n_patches, uniform_lines(options.n_u));
      std::vector<double>              v = uniform_lines(options.n_v);
      // the mesh of the lines u (per patch) and v (shared)
      auto set_mesh = [&]() {
        options.n_u = u[0].size() - 1;
        options.n_v = v.size() - 1;
        mesh_vertices.assign(n_patches, {});
        for (unsigned int p = 0; p < n_patches; ++p)
          for (const double y : v)
            for (const double x : u[p])
              mesh_vertices[p].emplace_back(x, y);
      };
      pcout << "Adaptation: crack refinement, at most " << refinement.stages
            << " stages, marked fraction " << refinement.marked_fraction
            << "; maximising " << fitness_name() << "\n";
      const auto start  = std::chrono::steady_clock::now();
      Json       stages = Json::array();
      quiet             = true;
      double first = -std::numeric_limits<double>::infinity(), last = first;
      unsigned int n_stages = 0, n_split = 0;
      // the mesh of the last stage with a finite fitness
      KeptMesh     kept;
      unsigned int failed_stage = 0;
      for (unsigned int s = 0; s < refinement.stages; ++s)
        {
          set_mesh();
          std::vector<double> activity;
          const double        f       = evaluate_cracks(context, activity);
          const double        seconds = std::chrono::duration<double>(
                                   std::chrono::steady_clock::now() - start)
                                   .count();
          const auto &blocks = model->blocks();
          stages.push_back(report_stage(pcout,
                                        s,
                                        blocks.size(),
                                        options.n_u,
                                        options.n_v,
                                        refinement.split_blocks,
                                        f,
                                        seconds));
          ++n_stages;
          if (s == 0)
            first = f;
          if (!std::isfinite(f))
            {
              // a later stage that fails: its parent mesh is analysed
              if (s > 0)
                {
                  u              = kept.u;
                  v              = kept.v;
                  options.splits = kept.splits;
                  n_split        = kept.n_split;
                  failed_stage   = s;
                }
              break;
            }
          last = f;
          kept = {u, v, options.splits, n_split};
          if (refinement.split_blocks)
            {
              if (!split_marked_blocks(refinement,
                                       blocks,
                                       block_activity(activity),
                                       n_patches,
                                       options.splits,
                                       n_split))
                break;
              continue;
            }

          std::vector<std::vector<double>> su(n_patches,
                                              std::vector<double>(options.n_u,
                                                                  0.));
          std::vector<double>              sv(options.n_v, 0.);
          strip_activity(model->interfaces(),
                         blocks,
                         geometry->patches(),
                         u,
                         v,
                         activity,
                         su,
                         sv);
          std::vector<std::vector<bool>> mu;
          std::vector<bool>              mv;
          const unsigned int             n_mu =
            mark_strips(refinement, su, sv, options.n_u, mu, mv);
          const unsigned int n_mv = std::count(mv.begin(), mv.end(), true);
          if (n_mu + n_mv == 0 ||
              n_patches * (options.n_u + n_mu) * (options.n_v + n_mv) >
                refinement.max_blocks)
            break;
          for (unsigned int p = 0; p < n_patches; ++p)
            u[p] = split(u[p], mu[p]);
          v = split(v, mv);
        }
      set_mesh();
      quiet            = false;
      seconds_geometry = seconds_assembly = seconds_solve = 0;
      cpu_seconds_solve                                   = 0;
      n_solves = n_iterations = 0;
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();

      Json a           = Json::object();
      a["optimiser"]   = optimiser_name;
      a["fitness"]     = fitness_name();
      a["stages"]      = stages;
      a["evaluations"] = n_stages;
      a["seconds"]     = seconds;
      if (std::isfinite(first))
        a["uniform_fitness"] = first;
      if (std::isfinite(last))
        a["best_fitness"] = last;
      else
        a["stopped"] = "the uniform mesh gives no finite " + fitness_name();
      if (failed_stage > 0)
        a["stopped"] = "stage " + std::to_string(failed_stage) +
                       " gives no finite " + fitness_name() +
                       "; the mesh of the stage before is analysed";
      a["blocks_along_u"] = options.n_u;
      a["blocks_along_v"] = options.n_v;
      Json lines_u        = Json::array();
      for (const auto &x : u)
        lines_u.push_back(numbers(x));
      a["lines_u"]                  = lines_u;
      a["lines_v"]                  = numbers(v);
      a["blocks_split"]             = n_split;
      context.summary["adaptation"] = a;
      std::ostringstream line;
      line << "Adaptation: " << n_stages << " stages in "
           << std::setprecision(3) << seconds << " s; the final mesh has ";
      if (refinement.split_blocks)
        line << n_split << " blocks split (from " << options.n_u << " x "
             << options.n_v << " per patch)\n";
      else
        line << options.n_u << " x " << options.n_v << " blocks per patch\n";
      if (a.contains("stopped"))
        line << "Adaptation: stopped: " << a.at("stopped").get<std::string>()
             << (failed_stage > 0 ? "\n" : " (the result below says why)\n");
      pcout << line.str();
    }
  } // namespace analysis
} // namespace masonry

MASONRY_REGISTER_OPTIMISER(
  masonry::adaptation::CrackRefinement,
  "crack refinement",
  "Refinement where the mechanism cracks (not a gene optimiser): solve the "
  "uniform mesh, split the parameter strips whose blocks crack most "
  "(`Marked fraction' of the crack activity, `Marking') at their "
  "middle, solve again, `Stages' times; then analyse the last mesh. The "
  "meshes are nested, so a settlement's objective never decreases from "
  "one stage to the next. `settlement' only; the entries of `Adaptation' "
  "other than this subsection are not used.")
