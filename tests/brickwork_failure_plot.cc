/**
 * The postprocessor `failure plot' (failure.png, failure.json and the
 * counts in summary.json), on the split unit of brickwork_splitting: one
 * elastic unit meshed as two halves joined by a splitting interface, between
 * fixed platens. With nu = -0.25 the restrained lateral contraction opens
 * the interface at strain 3.75e-4 (closed form in brickwork_splitting.cc);
 * with nu = 0.15 it stays closed.
 *
 * Checked: failure.png is a PNG of the requested size; the open joints it
 * draws (failure.json, summary.json) are the faces of the last
 * interfaces_NNNN.vtu whose normal_opening exceeds the threshold, counted
 * here from that file; the opened unit has open splitting faces only, the
 * closed one none; a run that does not list the postprocessor writes no
 * failure.png.
 */
#include <filesystem>
#include <fstream>
#include <sstream>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const double threshold = 1e-7; // m

  std::string
  unit(const double nu, const bool listed)
  {
    std::ostringstream m;
    if (listed)
      m << "subsection Postprocess\n"
           "  subsection Wallette\n"
           "    set List of postprocessors = curve tables, joint fields, "
           "failure plot\n"
           "    subsection Failure plot\n"
           "      set Opening threshold = "
        << threshold
        << "\n"
           "      set Width = 640\n"
           "      set Height = 360\n"
           "    end\n"
           "  end\n"
           "end\n";
    return splitting_unit(nu,
                          0.0005,
                          100,
                          "  set Output interval = 1000\n"
                          "  set Write VTU = true\n",
                          m.str());
  }

  /** Width and height of a PNG file (0, 0 if it is not one). */
  std::pair<unsigned int, unsigned int>
  png_size(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    char          b[24] = {};
    in.read(b, 24);
    const std::string signature("\x89PNG\r\n\x1a\n", 8);
    if (!in || std::string(b, 8) != signature ||
        std::string(b + 12, 4) != "IHDR")
      return {0, 0};
    auto be = [&](const int i) {
      unsigned int v = 0;
      for (int k = 0; k < 4; ++k)
        v = (v << 8) | static_cast<unsigned char>(b[i + k]);
      return v;
    };
    return {be(16), be(20)};
  }

  /** Faces of the last interfaces VTU of run @p name with normal_opening
   * above the threshold, and their joint types. */
  std::vector<int>
  open_faces_in_vtu(const std::string &name)
  {
    const auto entries     = pvd_entries("results/" + name + "/interfaces.pvd");
    const std::string last = entries.back();
    const auto        a    = last.find("file=\"") + 6;
    std::ifstream     in("results/" + name + "/" +
                     last.substr(a, last.find('"', a) - a));
    std::stringstream text;
    text << in.rdbuf();
    const std::string vtu   = text.str();
    auto              array = [&](const std::string &field) {
      std::vector<double> values;
      auto                i = vtu.find("Name=\"" + field + "\"");
      if (i == std::string::npos)
        return values;
      i = vtu.find('>', i) + 1;
      std::istringstream s(vtu.substr(i, vtu.find('<', i) - i));
      double             x;
      while (s >> x)
        values.push_back(x);
      return values;
    };
    const auto       opening = array("normal_opening");
    const auto       type = array("joint_type_bed0_head1_collar2_splitting3");
    std::vector<int> open;
    for (unsigned int i = 0; i < opening.size(); ++i)
      if (opening[i] > threshold)
        open.push_back(int(type[i]));
    return open;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    auto       summary = run("opened", unit(-0.25, true));
    const auto size    = png_size("results/opened/failure.png");
    check(size.first == 640 && size.second == 360,
          "failure.png written, a PNG of 640 x 360 pixels");
    const auto open = open_faces_in_vtu("opened");
    auto      &s    = summary["failure_plot"];
    check(!open.empty() && s["open_joints"].get<double>() == open.size() &&
            s["open_joints_splitting"].get<double>() == open.size(),
          "nu = -0.25: open joints drawn = faces of the last "
          "interfaces VTU with normal_opening > 1e-7 m (> 0), all "
          "splitting faces");
    std::ifstream     in("results/opened/failure.json");
    std::stringstream text;
    text << in.rdbuf();
    const auto data = masonry::parse_json(text.str());
    check(data.at("joints").size() == open.size() &&
            data.at("cells").size() == 40 * 8,
          "failure.json: the open faces and the 320 cells");
    check(s["displacement_magnification"].get<double>() > 0,
          "automatic displacement magnification stated");
  }
  {
    auto summary = run("closed", unit(0.15, true));
    check(open_faces_in_vtu("closed").empty() &&
            summary["failure_plot"]["open_joints"].get<double>() == 0 &&
            std::filesystem::exists("results/closed/failure.png"),
          "nu = 0.15: no open joint in the VTU, none drawn");
  }
  {
    run("unlisted", unit(-0.25, false));
    check(!std::filesystem::exists("results/unlisted/failure.png") &&
            !std::filesystem::exists("results/unlisted/failure.json"),
          "not listed: no failure.png, no failure.json");
  }
}
