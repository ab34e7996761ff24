/**
 * @file
 * The output directory of a run and the screen log that is copied to it.
 */
#ifndef masonry_core_output_directory_h
#define masonry_core_output_directory_h

#include <deal.II/base/mpi.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace masonry
{
  class OutputFile;

  /**
   * The directory a run writes into. It is created if missing (with its
   * parents) and checked for writing; files are named through file(), which
   * records them, so that summary.json lists exactly the files of this run
   * and a user is told which files of an earlier run are left untouched.
   */
  class OutputDirectory
  {
  public:
    /**
     * Create (rank 0) and check the directory @p path. Throws an
     * ExcParameter naming the entry `Output directory` if it cannot be
     * created or written.
     */
    OutputDirectory(const std::string &path, const MPI_Comm comm);

    /**
     * Check, without leaving a trace, that the directory @p path can be
     * created (or exists) and written into; throws an ExcParameter naming
     * `Output directory` otherwise. Used by `masonry --validate`.
     */
    static void
    check(const std::string &path, const MPI_Comm comm);

    /** The directory, ending in '/'. */
    const std::string &
    path() const;

    /**
     * Full path of the file @p name in the directory; records it as a file
     * of this run.
     */
    std::string
    file(const std::string &name);

    /** Files recorded by file(), in the order they were first named. */
    const std::vector<std::string> &
    files() const;

    /**
     * Files that an earlier run (as listed in the summary.json found on
     * start-up) wrote and this run did not: left untouched, but no longer
     * consistent with this run's results.
     */
    std::vector<std::string>
    stale_files() const;

    /** Whether the directory held results of an earlier run on start-up. */
    bool
    had_previous_run() const;

  private:
    std::string              directory;
    std::vector<std::string> written;
    std::vector<std::string> previous;
    bool                     previous_run = false;
  };

  /**
   * For files that every rank writes a share of: throws on every rank the
   * first non-empty @p error of any rank (in rank order), so that a write
   * that failed on one rank stops all of them together. Collective.
   */
  void
  throw_if_any_rank_failed(const std::string &error, const MPI_Comm comm);

  /**
   * The likely reason why a library that does not say (HDF5) could not write
   * into @p directory: "No space left on device" if the file system is
   * full, "File too large" under a file-size limit, else @p fallback.
   */
  std::string
  likely_write_reason(const std::string &directory,
                      const std::string &fallback);

  /**
   * Screen output of rank 0, copied to log.txt once the output directory is
   * known. Other ranks write nothing.
   */
  class Log
  {
  public:
    explicit Log(const MPI_Comm comm);
    ~Log();

    /** The stream to write progress and results to. */
    std::ostream &
    stream();

    /** Whether log.txt (if opened) was written without an error so far. */
    bool
    good() const;

    /**
     * Why log.txt could not be written ("cannot write '...': REASON"), or
     * "". A log.txt that could not be written whole is removed when the Log
     * is destroyed.
     */
    std::string
    error() const;

    /** Start copying everything written from now on to @p filename. */
    void
    open_file(const std::string &filename);

  private:
    class TeeBuffer;
    std::unique_ptr<OutputFile>   file;
    std::unique_ptr<TeeBuffer>    buffer;
    std::unique_ptr<std::ostream> out;
    std::string                   open_error;
  };
} // namespace masonry

#endif
