#include <masonry/analysis/interface.h>
#include <masonry/config.h>
#include <masonry/core/application.h>
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>
#include <masonry/core/usage.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <ctime>
#include <dlfcn.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

namespace masonry
{
  namespace
  {
    const char *usage = usage_text;

    /**
     * How long (s) a rank whose analysis threw waits for the others to
     * throw as well before it takes the error for its own and ends every
     * rank: an error every rank sees is met within milliseconds.
     */
    constexpr double rank_error_wait = 10;

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
      std::istringstream text(read_parameter_text(file));
      try
        {
          prm.parse_input(text, file, "", true);
        }
      catch (const std::exception &exc)
        {
          throw dealii::ExcMessage(explain_parse_error(one_line_message(exc)));
        }
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

    /**
     * Parse @p file into @p prm, with clear errors for a missing file, an
     * include cycle, a file that sets no Analysis (unless @p defaults) and
     * values out of their range.
     */
    void
    read_parameter_file(dealii::ParameterHandler &prm,
                        const std::string        &file,
                        const bool                defaults)
    {
      load_shared_libraries(file);
      declare_all_parameters(prm);
      std::istringstream text(read_parameter_text(file));
      try
        {
          prm.parse_input(text, file, "", false);
        }
      catch (const std::exception &exc)
        {
          throw dealii::ExcMessage(explain_parse_error(one_line_message(exc)));
        }
      AssertThrow(defaults || parameter_is_set("Analysis"),
                  dealii::ExcMessage(
                    file + ": no Analysis set (" +
                    (std::filesystem::is_empty(file) ?
                       std::string("the file is empty") :
                       std::string("no `set Analysis = ...'")) +
                    "; masonry --defaults " + file +
                    " runs the default analysis)"));
      check_parameter_values(prm);
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

    /**
     * The files of a run for its last line: a series of four or more files
     * that differ only in a step number after an underscore (solution_0020.vtu,
     * solution_0040.vtu, ...) is named once with `*` for the number and its
     * count, so a cyclic run of a thousand steps does not print a hundred
     * names.
     */
    std::string
    join_series(const std::vector<std::string> &files)
    {
      std::vector<std::string>                        keys;
      std::map<std::string, std::vector<std::string>> members;
      for (const auto &file : files)
        {
          std::string key        = file;
          const auto  underscore = file.rfind('_');
          if (underscore != std::string::npos)
            {
              auto end = underscore + 1;
              while (end < file.size() &&
                     std::isdigit(static_cast<unsigned char>(file[end])))
                ++end;
              if (end > underscore + 1)
                key = file.substr(0, underscore + 1) + "*" + file.substr(end);
            }
          if (members[key].empty())
            keys.push_back(key);
          members[key].push_back(file);
        }
      std::vector<std::string> names;
      for (const auto &key : keys)
        {
          const auto &list = members[key];
          if (list.size() >= 4)
            names.push_back(key + " (" + std::to_string(list.size()) +
                            " files)");
          else
            names.insert(names.end(), list.begin(), list.end());
        }
      return join(names);
    }

    /** Statuses that are no result of the analysis: the run failed. */
    bool
    is_failure(const std::string &status)
    {
      return status == "not converged" || status == "failed" ||
             status == "stalled" || status == "error";
    }

    /**
     * The files of @p output that this run was to write but did not (not a
     * regular file, or older than @p start): "name (reason)".
     */
    std::vector<std::string>
    unwritten_files(const OutputDirectory                &output,
                    const std::filesystem::file_time_type start,
                    const std::vector<std::string>       &skip)
    {
      namespace fs = std::filesystem;
      std::vector<std::string> missing;
      for (const auto &name : output.files())
        {
          if (std::find(skip.begin(), skip.end(), name) != skip.end())
            continue;
          const std::string path = output.path() + name;
          std::error_code   ec;
          if (fs::is_directory(path, ec))
            missing.push_back(name + " (a directory of that name exists)");
          else if (!fs::is_regular_file(path, ec))
            missing.push_back(name + " (not written)");
          else if (fs::last_write_time(path, ec) < start || ec)
            missing.push_back(name + " (not updated: left from an earlier "
                                     "run)");
        }
      return missing;
    }

    /**
     * Non-finite numbers in the CSV files of @p output: "file:line".
     * (Numbers printed by C++ streams as nan, inf, -nan.)
     */
    std::vector<std::string>
    non_finite_in_csv(const OutputDirectory &output)
    {
      std::vector<std::string> found;
      for (const auto &name : output.files())
        {
          if (name.size() < 4 || name.substr(name.size() - 4) != ".csv")
            continue;
          std::ifstream in(output.path() + name);
          std::string   line;
          unsigned int  number = 0;
          while (std::getline(in, line) && found.size() < 10)
            {
              ++number;
              if (number == 1)
                continue; // the header
              std::string lower;
              for (const char c : line)
                lower += static_cast<char>(
                  std::tolower(static_cast<unsigned char>(c)));
              for (const char *bad : {"nan", "inf"})
                {
                  const auto at = lower.find(bad);
                  if (at != std::string::npos &&
                      (at == 0 || !std::isalpha(
                                    static_cast<unsigned char>(lower[at - 1]))))
                    {
                      found.push_back(name + ":" + std::to_string(number));
                      break;
                    }
                }
            }
        }
      return found;
    }

    /**
     * Write summary.json on this rank, with its file list. Returns "" or why
     * it failed.
     */
    std::string
    write_summary_here(Json &summary, OutputDirectory &output)
    {
      output.file("summary.json");
      Json files = Json::array();
      for (const auto &f : output.files())
        files.push_back(f);
      summary["files"] = files;
      try
        {
          OutputFile out(output.path() + "summary.json");
          out << summary.dump(2) << "\n";
          out.close();
        }
      catch (const std::exception &exc)
        {
          return one_line_message(exc);
        }
      return {};
    }

    /**
     * Write summary.json (rank 0); returns "" or why it failed, on every
     * rank.
     */
    std::string
    write_summary_file(Json            &summary,
                       OutputDirectory &output,
                       const MPI_Comm   comm)
    {
      std::string error;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        error = write_summary_here(summary, output);
      else
        output.file("summary.json");
      return dealii::Utilities::MPI::broadcast(comm, error, 0);
    }

    /**
     * Whether every rank of @p error_comm reaches this call within
     * @p seconds: a rank whose analysis threw calls it, and if the others
     * threw too (an error every rank sees), they meet here. A rank whose
     * error the others did not see finds them still computing, or waiting in
     * one of the analysis' collective operations that this rank will never
     * join; it must end the run for all (MPI_Abort) instead of waiting.
     * @p error_comm is a duplicate of the run's communicator used for nothing
     * else, so that this barrier cannot match any other collective call.
     */
    bool
    all_ranks_failed(const MPI_Comm error_comm, const double seconds)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(error_comm) == 1)
        return true;
      MPI_Request request;
      MPI_Ibarrier(error_comm, &request);
      const auto until = std::chrono::steady_clock::now() +
                         std::chrono::duration<double>(seconds);
      int done = 0;
      while (!done)
        {
          MPI_Test(&request, &done, MPI_STATUS_IGNORE);
          if (done || std::chrono::steady_clock::now() > until)
            break;
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      return done != 0;
    }

    /**
     * Why the results of a completed analysis are not usable (a non-finite
     * CSV entry, a file that was not written, a log that could not be
     * written), or "". (A non-finite entry of summary.json is found when the
     * summary is written: non_finite_message().)
     */
    std::string
    result_problem(const OutputDirectory                 &output,
                   const Log                             &log,
                   const std::filesystem::file_time_type &file_start)
    {
      const auto csv = non_finite_in_csv(output);
      if (!csv.empty())
        return "non-finite numbers (nan/inf) in " + join(csv) +
               " (a value out of its physical range in the parameter file?)";
      const auto missing =
        unwritten_files(output, file_start, {"summary.json"});
      if (!missing.empty())
        return "result files could not be written: " + join(missing);
      if (!log.good())
        return log.error();
      return {};
    }

    /**
     * The run's first lines on @p pcout: the version, the analysis of
     * @p file (read into @p prm), the number of MPI ranks of @p comm if
     * more than one, and the output directory.
     */
    void
    announce_run(dealii::ConditionalOStream     &pcout,
                 const dealii::ParameterHandler &prm,
                 const std::string              &file,
                 const OutputDirectory          &output,
                 const MPI_Comm                  comm)
    {
      pcout << "masonry " << MASONRY_VERSION << ": " << prm.get("Analysis")
            << " analysis of " << file;
      if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        pcout << " on " << dealii::Utilities::MPI::n_mpi_processes(comm)
              << " MPI ranks";
      pcout << "\nOutput directory: " << output.path() << "\n";
      if (output.had_previous_run())
        pcout << "  (holds an earlier run: the files this run writes are "
                 "overwritten, the others are left alone)\n";
    }

    /**
     * parameters.prm in @p output: every parameter of @p prm as the run
     * uses it. Throws on every rank of @p comm if rank 0 could not write
     * it.
     */
    void
    write_used_parameters(const dealii::ParameterHandler &prm,
                          OutputDirectory                &output,
                          const MPI_Comm                  comm)
    {
      const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      // rank 0 writes; every rank learns of a failure (no rank may go on
      // into the analysis' collective operations alone)
      std::string       prm_error;
      const std::string used_name = output.file("parameters.prm");
      if (root)
        try
          {
            OutputFile used(used_name);
            prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
            used.close();
          }
        catch (const std::exception &exc)
          {
            prm_error = one_line_message(exc);
          }
      prm_error = dealii::Utilities::MPI::broadcast(comm, prm_error, 0);
      AssertThrow(prm_error.empty(), dealii::ExcMessage(prm_error));
    }

    /**
     * For an analysis stopped by a non-finite number in @p summary: the
     * member that was to hold it (created null before the value failed)
     * taken out of @p summary and named in `non_finite_results`; returns
     * the run's error message.
     */
    std::string
    non_finite_message(Json &summary)
    {
      // the member it was meant for was created (null) before the
      // value failed: name it, and leave it out of summary.json
      const std::string path = first_null_member(summary);
      if (!path.empty())
        {
          summary.erase(path.substr(0, path.find_first_of("/[")));
          summary["non_finite_results"] = Json::array({path});
        }
      return "the result '" + (path.empty() ? "?" : path) +
             "' is not a finite number (a value out of its "
             "physical range in the parameter file?)";
    }

    /**
     * An error of this rank alone, with @p status and @p message: written
     * to @p summary (summary.json in @p output, by this rank) and to
     * std::cerr, then every rank of @p comm ended by MPI_Abort.
     */
    void
    abort_all_ranks(const MPI_Comm     comm,
                    Json              &summary,
                    OutputDirectory   &output,
                    const std::string &status,
                    const std::string &message)
    {
      // an error of this rank alone: the others cannot be told, so
      // this rank says why, records it and ends every rank
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
      const std::string  text =
        "rank " + std::to_string(rank) + " of " +
        std::to_string(dealii::Utilities::MPI::n_mpi_processes(comm)) + ": " +
        message;
      summary["status"]               = status;
      summary["complete"]             = false;
      summary["error"]                = text;
      const std::string summary_error = write_summary_here(summary, output);
      std::cerr << "masonry: error: " << text << " [the results in "
                << output.path() << " are incomplete"
                << (summary_error.empty() ?
                      "; summary.json has status '" + status + "'" :
                      "; " + summary_error)
                << "; every rank is stopped]" << std::endl;
      MPI_Abort(comm, 1);
    }

    int
    run_file(const std::string &file, const MPI_Comm comm, const bool defaults)
    {
      const auto         start     = std::chrono::steady_clock::now();
      const std::clock_t cpu_start = std::clock();
      const auto         file_start =
        std::filesystem::file_time_type::clock::now() - std::chrono::seconds(2);
      const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

      dealii::ParameterHandler prm;
      read_parameter_file(prm, file, defaults);
      std::unique_ptr<analysis::Interface> analysis = create_analysis(prm);

      std::string directory = prm.get("Output directory");
      if (directory.empty())
        directory = default_output_directory(file);
      // before anything is written: the files of an earlier run stay as
      // they are if the analysis cannot start here (a resume without a
      // readable checkpoint)
      analysis->check_output_directory(directory, comm);
      plugins::ParsePathScope scope("");
      OutputDirectory         output(directory, comm);

      Log log(comm);
      log.open_file(output.file("log.txt"));
      const std::string log_error =
        dealii::Utilities::MPI::broadcast(comm, log.error(), 0);
      AssertThrow(log_error.empty(), dealii::ExcMessage(log_error));
      dealii::ConditionalOStream pcout(log.stream(), true);

      announce_run(pcout, prm, file, output, comm);

      write_used_parameters(prm, output, comm);

      Json summary               = Json::object();
      summary["analysis"]        = prm.get("Analysis");
      summary["status"]          = "running";
      summary["complete"]        = false;
      summary["wall_seconds"]    = 0.0;
      summary["cpu_seconds"]     = 0.0;
      summary["masonry_version"] = MASONRY_VERSION;
      summary["n_mpi_ranks"]    = dealii::Utilities::MPI::n_mpi_processes(comm);
      summary["parameter_file"] = file;

      // writes summary.json (rank 0); returns "" or why it failed
      auto write_summary = [&]() {
        summary["wall_seconds"] = std::chrono::duration<double>(
                                    std::chrono::steady_clock::now() - start)
                                    .count();
        summary["cpu_seconds"] =
          double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
        return write_summary_file(summary, output, comm);
      };

      // a run that gives no result: summary.json says so, exit code 1
      auto fail = [&](const std::string &status, const std::string &message) {
        summary["status"]               = status;
        summary["complete"]             = false;
        summary["error"]                = message;
        const std::string summary_error = write_summary();
        pcout << "Run stopped: " << message << "\n";
        throw dealii::ExcMessage(
          message + " [the results in " + output.path() + " are incomplete" +
          (summary_error.empty() ?
             "; summary.json has status '" + status + "'" :
             "; " + summary_error) +
          "]");
      };

      // a run that is killed leaves a summary.json that says so (status
      // `running', not complete) rather than an earlier run's
      const std::string start_problem = write_summary();
      AssertThrow(start_problem.empty(), dealii::ExcMessage(start_problem));

      RunContext context{comm, pcout, output, summary};
      MPI_Comm   error_comm =
        dealii::Utilities::MPI::duplicate_communicator(comm);
      try
        {
          analysis->run(context);
        }
      catch (const std::exception &exc)
        {
          std::string message = one_line_message(exc);
          std::string status  = "error";
          if (dynamic_cast<const NonFiniteJsonNumber *>(&exc) != nullptr)
            {
              message = non_finite_message(summary);
              status  = "failed";
            }
          if (!all_ranks_failed(error_comm, rank_error_wait))
            abort_all_ranks(comm, summary, output, status, message);
          dealii::Utilities::MPI::free_communicator(error_comm);
          fail(status, message);
        }
      dealii::Utilities::MPI::free_communicator(error_comm);
      if (summary.at("status").get<std::string>() == "running")
        summary["status"] = "completed";
      const std::string status = summary.at("status").get<std::string>();
      if (is_failure(status))
        {
          // the analysis' own words on why there is no result
          std::string why;
          for (const char *key : {"explanation", "message"})
            if (why.empty() && summary.contains(key) &&
                summary.at(key).is_string())
              why = ": " + summary.at(key).get<std::string>();
          summary["analysis_status"] = status;
          fail("failed",
               "the analysis ended with status '" + status + "'" + why +
                 " (no result)");
        }

      // every result must be finite and every file written
      std::string problem;
      if (root)
        problem = result_problem(output, log, file_start);
      problem = dealii::Utilities::MPI::broadcast(comm, problem, 0);
      if (!problem.empty())
        fail("failed", problem);

      summary["complete"]               = true;
      const std::string summary_problem = write_summary();
      AssertThrow(summary_problem.empty(), dealii::ExcMessage(summary_problem));

      const auto stale = output.stale_files();
      if (!stale.empty())
        pcout << "Note: files of an earlier run left in " << output.path()
              << " (not written by this run): " << join(stale) << "\n";
      pcout << "Status: " << summary.at("status").get<std::string>() << "\n"
            << "Results: " << output.path() << " ("
            << join_series(output.files()) << ")\n"
            << "Wall time: " << std::fixed << std::setprecision(2)
            << summary.at("wall_seconds").get<double>() << " s\n";
      return 0;
    }
  } // namespace

  void
  declare_all_parameters(dealii::ParameterHandler &prm)
  {
    declare_driver_parameters(prm);
    for (const auto &subsystem : plugins::subsystems())
      subsystem.declare(prm);
    declare_parameter_ranges(prm);
  }

  int
  run_application(const std::vector<std::string> &all_arguments,
                  const MPI_Comm                  comm)
  {
    // without MPI_Init (masonry_validate(): --validate of a single
    // process) this process is the only rank
    int mpi_running = 0;
    MPI_Initialized(&mpi_running);
    const bool root =
      !mpi_running || dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    std::string option;
    try
      {
        std::vector<std::string> arguments;
        bool                     defaults = false;
        for (const auto &a : all_arguments)
          if (a == "--defaults")
            defaults = true;
          else
            arguments.push_back(a);
        AssertThrow(!defaults || !arguments.empty(),
                    dealii::ExcMessage("--defaults needs a parameter file"));
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
            read_parameter_file(prm, arguments[1], defaults);
            const auto  analysis  = create_analysis(prm);
            std::string directory = prm.get("Output directory");
            if (directory.empty())
              directory = default_output_directory(arguments[1]);
            OutputDirectory::check(directory, comm);
            analysis->check_output_directory(directory, comm);
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
        return run_file(arguments[0], comm, defaults);
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

/**
 * The entry point that the `masonry` launcher (source/main.cc) finds with
 * dlsym(): MPI_Init, run_application() on the arguments, MPI_Finalize.
 */
extern "C" int
masonry_main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  const std::vector<std::string>           arguments(argv + 1, argv + argc);
  return masonry::run_application(arguments, MPI_COMM_WORLD);
}

/**
 * The entry point of `masonry --validate FILE` in a process that no MPI
 * launcher started: run_application() without MPI_Init. Reading and
 * checking a file needs no communication, and MPI_Init (with the
 * libraries deal.II initialises with it: PETSc, SLEPc, p4est, Zoltan) and
 * the Open MPI daemon a singleton starts were a third of the CPU time of
 * such a call (contrib/benchmarks/startup). Any other command goes to
 * masonry_main(). The output is flushed before the return: the launcher
 * ends the process without the libraries' static destructors.
 */
extern "C" int
masonry_validate(int argc, char **argv)
{
  std::vector<std::string> arguments;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) != "--defaults")
      arguments.emplace_back(argv[i]);
  if (arguments.empty() || arguments[0] != "--validate")
    return masonry_main(argc, argv);
  const int status =
    masonry::run_application(std::vector<std::string>(argv + 1, argv + argc),
                             MPI_COMM_SELF);
  // the launcher ends the process with _Exit() after this call
  std::cout.flush();
  std::cerr.flush();
  return status;
}
