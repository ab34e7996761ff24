#include <masonry/analysis/interface.h>
#include <masonry/config.h>
#include <masonry/core/application.h>
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <dlfcn.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace masonry
{
  namespace
  {
    const char *usage =
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
      "  --validate FILE.prm        check FILE.prm (entries, values, files) "
      "without running\n"
      "  --print-parameters[=prm|json]\n"
      "                             write every parameter of every plugin "
      "with its\n"
      "                             documentation and default, then exit\n"
      "  --version                  print the version and exit\n"
      "  --help                     print this text and exit\n"
      "\n"
      "Runs in parallel under mpirun; only rank 0 writes to the screen.\n";

    /** Declare the driver's own top-level entries. */
    void
    declare_driver_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Output directory",
        "",
        dealii::Patterns::Anything(),
        "Directory for the results of the run, created if missing. Empty: "
        "output/<stem of the parameter file> relative to the working "
        "directory. Files of an earlier run that this run writes are "
        "overwritten; the others are left alone and listed on screen.");
      prm.declare_entry(
        "Additional shared libraries",
        "",
        dealii::Patterns::List(dealii::Patterns::FileName()),
        "Comma-separated list of shared libraries with user plugins, loaded "
        "before the parameters are declared so that their plugins can be "
        "selected in this file. Build them with find_package(masonry); see "
        "contrib/examples/plugin.");
    }

    /**
     * Load the libraries named in `Additional shared libraries` of @p file,
     * reading nothing else of it.
     */
    void
    load_shared_libraries(const std::string &file)
    {
      dealii::ParameterHandler prm;
      declare_driver_parameters(prm);
      // for the location in the error message of a library that is missing
      record_parameter_locations(file);
      prm.parse_input(file, "", true);
      const auto libraries = dealii::Utilities::split_string_list(
        prm.get("Additional shared libraries"), ',');
      for (const auto &library : libraries)
        {
          // a name without '/' is looked up by dlopen in the system paths;
          // users mean the working directory, as in ASPECT
          const std::string path =
            library.find('/') == std::string::npos ? "./" + library : library;
          void *handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
          if (handle == nullptr)
            {
              const char *reason = dlerror();
              throw dealii::ExcMessage(
                parameter_location("Additional shared libraries") +
                ": entry 'Additional shared libraries': cannot load '" +
                library + "': " + (reason ? reason : "unknown reason"));
            }
        }
    }

    std::string
    default_output_directory(const std::string &file)
    {
      return "output/" + std::filesystem::path(file).stem().string();
    }

    /** Parse @p file into @p prm, with clear errors for a missing file. */
    void
    read_parameter_file(dealii::ParameterHandler &prm, const std::string &file)
    {
      {
        std::ifstream in(file);
        AssertThrow(in.good(),
                    dealii::ExcMessage(file +
                                       ": cannot open the parameter file"));
        AssertThrow(!std::filesystem::is_directory(file),
                    dealii::ExcMessage(file + ": is a directory, not a "
                                              "parameter file"));
      }
      load_shared_libraries(file);
      declare_all_parameters(prm);
      record_parameter_locations(file);
      try
        {
          prm.parse_input(file);
        }
      catch (const std::exception &exc)
        {
          throw dealii::ExcMessage(explain_parse_error(one_line_message(exc)));
        }
    }

    /** Create and set up the analysis: every input check happens here. */
    std::unique_ptr<analysis::Interface>
    create_analysis(dealii::ParameterHandler &prm)
    {
      auto analysis = plugins::Registry<analysis::Interface>::create(prm);
      analysis->setup(prm);
      return analysis;
    }

    std::string
    join(const std::vector<std::string> &list)
    {
      std::string s;
      for (const auto &item : list)
        s += (s.empty() ? "" : ", ") + item;
      return s;
    }

    int
    run_file(const std::string &file, const MPI_Comm comm)
    {
      const auto start = std::chrono::steady_clock::now();

      dealii::ParameterHandler prm;
      read_parameter_file(prm, file);
      std::unique_ptr<analysis::Interface> analysis = create_analysis(prm);

      std::string directory = prm.get("Output directory");
      if (directory.empty())
        directory = default_output_directory(file);
      plugins::ParsePathScope scope("");
      OutputDirectory         output(directory, comm);

      Log log(comm);
      log.open_file(output.file("log.txt"));
      dealii::ConditionalOStream pcout(log.stream(), true);

      pcout << "masonry " << MASONRY_VERSION << ": " << prm.get("Analysis")
            << " analysis of " << file;
      if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        pcout << " on " << dealii::Utilities::MPI::n_mpi_processes(comm)
              << " MPI ranks";
      pcout << "\nOutput directory: " << output.path() << "\n";
      if (output.had_previous_run())
        pcout << "  (holds an earlier run: the files this run writes are "
                 "overwritten, the others are left alone)\n";

      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::ofstream used(output.file("parameters.prm"));
          prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
        }

      Json summary               = Json::object();
      summary["analysis"]        = prm.get("Analysis");
      summary["status"]          = "running";
      summary["wall_seconds"]    = 0.0;
      summary["masonry_version"] = MASONRY_VERSION;
      summary["n_mpi_ranks"]    = dealii::Utilities::MPI::n_mpi_processes(comm);
      summary["parameter_file"] = file;

      auto write_summary = [&]() {
        summary["wall_seconds"] = std::chrono::duration<double>(
                                    std::chrono::steady_clock::now() - start)
                                    .count();
        output.file("summary.json");
        Json files = Json::array();
        for (const auto &f : output.files())
          files.push_back(f);
        summary["files"] = files;
        if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
          {
            std::ofstream out(output.path() + "summary.json");
            out << summary.dump() << "\n";
          }
      };

      RunContext context{comm, pcout, output, summary};
      try
        {
          analysis->run(context);
        }
      catch (const std::exception &exc)
        {
          const std::string message = one_line_message(exc);
          summary["status"]         = "error";
          summary["error"]          = message;
          write_summary();
          pcout << "Run stopped: " << message << "\n";
          throw dealii::ExcMessage(
            message + " [the results in " + output.path() +
            " are incomplete; summary.json has status 'error']");
        }
      if (summary.at("status").as_string() == "running")
        summary["status"] = "completed";
      write_summary();

      const auto stale = output.stale_files();
      if (!stale.empty())
        pcout << "Note: files of an earlier run left in " << output.path()
              << " (not written by this run): " << join(stale) << "\n";
      pcout << "Status: " << summary.at("status").as_string() << "\n"
            << "Results: " << output.path() << " (" << join(output.files())
            << ")\n"
            << "Wall time: " << std::fixed << std::setprecision(2)
            << summary.at("wall_seconds").as_number() << " s\n";
      return 0;
    }
  } // namespace

  void
  declare_all_parameters(dealii::ParameterHandler &prm)
  {
    declare_driver_parameters(prm);
    for (const auto &subsystem : plugins::subsystems())
      subsystem.declare(prm);
  }

  int
  run_application(const std::vector<std::string> &arguments,
                  const MPI_Comm                  comm)
  {
    const bool  root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    std::string option;
    try
      {
        if (arguments.empty() || arguments[0] == "--help" ||
            arguments[0] == "-h")
          {
            if (root)
              (arguments.empty() ? std::cerr : std::cout) << usage;
            return arguments.empty() ? 2 : 0;
          }
        option = arguments[0];
        if (option == "--version")
          {
            if (root)
              std::cout << "masonry " << MASONRY_VERSION << "\n";
            return 0;
          }
        if (option.rfind("--print-parameters", 0) == 0)
          {
            const std::string format = option.size() > 18 && option[18] == '=' ?
                                         option.substr(19) :
                                         "prm";
            AssertThrow(format == "prm" || format == "json",
                        dealii::ExcMessage("--print-parameters takes =prm or "
                                           "=json, not '" +
                                           format + "'"));
            // user plugins: --print-parameters FILE.prm loads the file's
            // Additional shared libraries first
            if (arguments.size() > 1)
              load_shared_libraries(arguments[1]);
            dealii::ParameterHandler prm;
            declare_all_parameters(prm);
            if (root)
              prm.print_parameters(std::cout,
                                   format == "json" ?
                                     dealii::ParameterHandler::JSON :
                                     dealii::ParameterHandler::PRM);
            return 0;
          }
        if (option == "--validate")
          {
            AssertThrow(arguments.size() == 2,
                        dealii::ExcMessage(
                          "--validate takes exactly one parameter file"));
            dealii::ParameterHandler prm;
            read_parameter_file(prm, arguments[1]);
            create_analysis(prm);
            if (root)
              std::cout << arguments[1] << ": valid (" << prm.get("Analysis")
                        << " analysis)\n";
            return 0;
          }
        AssertThrow(option.empty() || option[0] != '-',
                    dealii::ExcMessage("unknown option '" + option +
                                       "' (see masonry --help)"));
        AssertThrow(arguments.size() == 1,
                    dealii::ExcMessage("masonry takes one parameter file, "
                                       "got " +
                                       std::to_string(arguments.size()) +
                                       " arguments (see masonry --help)"));
        return run_file(arguments[0], comm);
      }
    catch (const std::exception &exc)
      {
        if (root)
          std::cerr << "masonry: error: " << one_line_message(exc) << std::endl;
        return 1;
      }
    catch (...)
      {
        if (root)
          std::cerr << "masonry: error: unknown exception" << std::endl;
        return 1;
      }
  }
} // namespace masonry
