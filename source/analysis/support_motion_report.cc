/**
 * @file
 * The record of the support-motion check in summary.json
 * (support_motion_report.h).
 */
#include "support_motion_report.h"

namespace masonry
{
  namespace analysis
  {
    namespace
    {
      Json
      point_json(const dealii::Point<3> &p)
      {
        Json a = Json::array();
        for (unsigned int d = 0; d < 3; ++d)
          a.push_back(p[d]);
        return a;
      }
    } // namespace

    Json
    incompatibility_json(const rigid_blocks::Incompatibility &x)
    {
      Json i        = Json::object();
      i["kind"]     = x.kind;
      i["block"]    = x.block;
      i["patch"]    = x.patch;
      i["centroid"] = point_json(x.centroid);
      if (!x.support_label.empty())
        i["support_edge"] = x.support_label;
      if (x.kind != "support" &&
          x.other_block != rigid_blocks::Interface::support)
        i["other_block"] = x.other_block;
      i["position"] = point_json(x.position);
      i["misfit"]   = x.misfit;
      if (x.kind == "lp")
        {
          i["direction"]    = x.direction;
          i["total_misfit"] = x.total_misfit;
        }
      else
        i["rms_misfit"] = x.rms_misfit;
      i["count"]   = x.n_found;
      i["message"] = x.describe();
      return i;
    }

    void
    record_support_check(const rigid_blocks::SupportCheck &check, Json &summary)
    {
      Json c                   = Json::object();
      c["largest_misfit"]      = check.largest_misfit;
      c["tolerance"]           = check.tolerance;
      c["exact"]               = check.exact;
      c["supported_groups"]    = check.n_supported_groups;
      c["fixed_groups"]        = check.n_fixed_groups;
      summary["support_check"] = c;
      if (check.incompatible)
        summary["incompatibility"] = incompatibility_json(check.worst);
    }
  } // namespace analysis
} // namespace masonry
