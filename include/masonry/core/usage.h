/**
 * @file
 * The text of `masonry --help`, shared by the launcher executable (which
 * answers --help without loading libmasonry) and run_application().
 */
#ifndef masonry_core_usage_h
#define masonry_core_usage_h

namespace masonry
{
  inline constexpr const char *usage_text =
    "Usage: masonry [OPTION] FILE.prm\n"
    "\n"
    "Runs the analysis selected by `set Analysis = ...` in FILE.prm and "
    "writes its\n"
    "results into `Output directory` (default output/<FILE stem>): "
    "parameters.prm,\n"
    "log.txt, summary.json and the analysis' own files.\n"
    "\n"
    "Options:\n"
    "  FILE.prm                   run the analysis described in FILE.prm\n"
    "  --validate FILE.prm        check FILE.prm (entries, values, "
    "expressions,\n"
    "                             output directory) without running\n"
    "  --defaults FILE.prm        also accept a file that sets no "
    "Analysis (runs the\n"
    "                             default analysis; with or after "
    "--validate too)\n"
    "  --print-parameters[=prm|json]\n"
    "                             write every parameter of every plugin "
    "with its\n"
    "                             documentation and default, then exit\n"
    "  --version                  print the version and exit\n"
    "  --help                     print this text and exit\n"
    "\n"
    "Runs in parallel under mpirun; only rank 0 writes to the screen.\n"
    "Exit code: 0 for a result (also `mechanism', `incompatible', "
    "`no_collapse'),\n"
    "1 for an error or a run without a result (`not converged', "
    "`failed'), 2 without\n"
    "arguments.\n";
} // namespace masonry

#endif
