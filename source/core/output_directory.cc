#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <streambuf>
#include <sys/resource.h>
#include <sys/statvfs.h>

namespace masonry
{
  namespace
  {
    /**
     * Create @p directory (with its parents) and check that a file can be
     * written into it. Returns an error message, empty on success.
     */
    std::string
    create_writable(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      fs::create_directories(directory, ec);
      if (ec)
        return "cannot create '" + directory + "': " + ec.message();
      if (!fs::is_directory(directory, ec))
        return "'" + directory + "' is not a directory";
      const std::string probe = directory + ".masonry-write-test";
      std::string       error;
      {
        std::ofstream test(probe);
        test << "test\n";
        test.close();
        if (!test)
          error = "cannot write into '" + directory + "'";
      }
      fs::remove(probe, ec);
      return error;
    }
  } // namespace

  OutputDirectory::OutputDirectory(const std::string &path, const MPI_Comm comm)
    : directory(path.empty() || path.back() == '/' ? path : path + "/")
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        error = create_writable(directory);
        if (error.empty())
          {
            std::ifstream old(directory + "summary.json");
            if (old)
              {
                previous_run = true;
                std::stringstream text;
                text << old.rdbuf();
                try
                  {
                    const Json summary = parse_json(text.str());
                    if (summary.contains("files"))
                      for (std::size_t i = 0; i < summary.at("files").size();
                           ++i)
                        previous.push_back(
                          summary.at("files").at(i).get<std::string>());
                  }
                catch (...)
                  {
                    // an unreadable old summary only means we cannot list
                    // its files; the run itself is not affected
                  }
              }
          }
      }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), ExcParameter("Output directory", error));
  }

  void
  OutputDirectory::check(const std::string &path, const MPI_Comm comm)
  {
    namespace fs = std::filesystem;
    // also called without MPI_Init (masonry --validate): one rank then
    int mpi_running = 0;
    MPI_Initialized(&mpi_running);
    std::string error;
    if (!mpi_running || dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const std::string directory =
          path.empty() || path.back() == '/' ? path : path + "/";
        // the directories that do not exist yet, outermost first
        std::vector<fs::path> created;
        std::error_code       ec;
        fs::path p = fs::absolute(directory, ec).lexically_normal();
        if (!p.has_filename())
          p = p.parent_path();
        for (fs::path q = p; !q.empty() && !fs::exists(q, ec);
             q          = q.parent_path())
          {
                     created.insert(created.begin(), q);
                     if (q == q.parent_path())
              break;
          }
        error = create_writable(directory);
        for (auto it = created.rbegin(); it != created.rend(); ++it)
          fs::remove(*it, ec);
      }
    if (mpi_running)
      error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), ExcParameter("Output directory", error));
  }

  const std::string &
  OutputDirectory::path() const
  {
    return directory;
  }

  std::string
  OutputDirectory::file(const std::string &name)
  {
    if (std::find(written.begin(), written.end(), name) == written.end())
      written.push_back(name);
    return directory + name;
  }

  const std::vector<std::string> &
  OutputDirectory::files() const
  {
    return written;
  }

  std::vector<std::string>
  OutputDirectory::stale_files() const
  {
    std::vector<std::string> stale;
    for (const auto &f : previous)
      if (std::find(written.begin(), written.end(), f) == written.end() &&
          std::filesystem::exists(directory + f))
        stale.push_back(f);
    return stale;
  }

  bool
  OutputDirectory::had_previous_run() const
  {
    return previous_run;
  }

  void
  throw_if_any_rank_failed(const std::string &error, const MPI_Comm comm)
  {
    for (const auto &e : dealii::Utilities::MPI::all_gather(comm, error))
      AssertThrow(e.empty(), dealii::ExcMessage(e));
  }

  std::string
  likely_write_reason(const std::string &directory, const std::string &fallback)
  {
    struct statvfs fs;
    if (::statvfs(directory.c_str(), &fs) == 0 && fs.f_bavail == 0)
      return "No space left on device";
    struct rlimit limit;
    if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
        limit.rlim_cur != RLIM_INFINITY)
      return "File too large (a file-size limit of " +
             std::to_string(limit.rlim_cur) + " bytes)";
    return fallback;
  }

  /** A stream buffer writing to the screen and, once opened, to a file. */
  class Log::TeeBuffer : public std::streambuf
  {
  public:
    TeeBuffer(std::streambuf *screen)
      : screen(screen)
    {}

    std::streambuf *screen;
    std::streambuf *file = nullptr;

  protected:
    int
    overflow(int c) override
    {
      if (c == EOF)
        return !EOF;
      if (screen != nullptr)
        screen->sputc(static_cast<char>(c));
      if (file != nullptr)
        file->sputc(static_cast<char>(c));
      // every line reaches the screen and log.txt at once, also when the
      // screen is a file or a pipe (progress of long runs)
      if (c == '\n')
        sync();
      return c;
    }

    std::streamsize
    xsputn(const char *s, std::streamsize n) override
    {
      if (screen != nullptr)
        screen->sputn(s, n);
      if (file != nullptr)
        file->sputn(s, n);
      if (std::char_traits<char>::find(s, n, '\n') != nullptr)
        sync();
      return n;
    }

    int
    sync() override
    {
      if (screen != nullptr)
        screen->pubsync();
      if (file != nullptr)
        file->pubsync();
      return 0;
    }
  };

  Log::Log(const MPI_Comm comm)
    : buffer(std::make_unique<TeeBuffer>(
        dealii::Utilities::MPI::this_mpi_process(comm) == 0 ?
          std::cout.rdbuf() :
          nullptr))
    , out(std::make_unique<std::ostream>(buffer.get()))
  {}

  Log::~Log()
  {
    out->flush();
    if (file != nullptr)
      try
        {
          // written in place: renames nothing, removes an incomplete log
          file->close();
        }
      catch (...)
        {
          // the run has said why (error()); a destructor must not throw
        }
  }

  std::ostream &
  Log::stream()
  {
    return *out;
  }

  bool
  Log::good() const
  {
    if (file == nullptr)
      return open_error.empty();
    file->flush();
    return file->good();
  }

  std::string
  Log::error() const
  {
    if (file == nullptr)
      return open_error;
    file->flush();
    return file->error();
  }

  void
  Log::open_file(const std::string &filename)
  {
    if (buffer->screen == nullptr)
      return;
    try
      {
        file = std::make_unique<OutputFile>(filename, true);
      }
    catch (const std::exception &exc)
      {
        // said by error(): the caller decides with every rank what to do
        open_error = one_line_message(exc);
        return;
      }
    buffer->file = file->rdbuf();
  }
} // namespace masonry
