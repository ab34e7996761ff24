/**
 * @file
 * Output files that are whole or absent: written under a temporary name in
 * their directory and renamed to their final name only once every byte is on
 * the file system. A full disk, an I/O error or a file-size limit ends the
 * write with an error naming the file and the system's reason.
 */
#ifndef masonry_core_output_file_h
#define masonry_core_output_file_h

#include <memory>
#include <ostream>
#include <string>

namespace masonry
{
  /**
   * The name under which the file @p path is written before it is whole:
   * hidden, in the same directory (so that the rename is atomic), with the
   * process id (two processes never share it) and the same extension (some
   * writers choose the format by it): `dir/.name.PID.part.ext`.
   */
  std::string
  temporary_file_name(const std::string &path);

  /**
   * The one-line error for a file that could not be written:
   * "cannot write 'PATH': REASON" (REASON as the system gives it, e.g.
   * "No space left on device").
   */
  std::string
  write_error(const std::string &path, const std::string &reason);

  /**
   * A file written by this program's own streams. Write to it like an
   * std::ofstream, then call close(): only then does the file appear under
   * its name. If close() is not reached (an exception, a write error), the
   * temporary file is removed and an earlier file of that name is left
   * unchanged.
   *
   * Unlike std::ofstream, every failed system call keeps its reason (errno),
   * so that the error says "No space left on device" rather than "cannot
   * write".
   */
  class OutputFile : public std::ostream
  {
  public:
    /**
     * Open the temporary file of @p path. Throws an ExcMessage naming @p path
     * and the reason if it cannot be created.
     *
     * With @p in_place, the file is written under its final name from the
     * start, for a log that a user follows while the run goes on; if a
     * write fails, close() or the destructor removes it, so that it is
     * still whole or absent.
     */
    explicit OutputFile(const std::string &path, const bool in_place = false);

    /** Removes the temporary file if close() was not called or failed. */
    ~OutputFile() override;

    OutputFile(const OutputFile &) = delete;
    OutputFile &
    operator=(const OutputFile &) = delete;

    /**
     * Write out what is buffered, close, and rename the file to its name.
     * Throws an ExcMessage "cannot write 'PATH': REASON" if any write, the
     * close or the rename failed; the temporary file is then removed.
     */
    void
    close();

    /** The final name of the file. */
    const std::string &
    path() const;

    /**
     * "" while every write succeeded, else the one-line error naming the file
     * and the system's reason.
     */
    std::string
    error() const;

  private:
    class Buffer;
    std::string             final_path;
    std::string             written_path;
    std::unique_ptr<Buffer> buffer;
    bool                    closed = false;
  };

  /**
   * A file that another library writes by name (deal.II's parallel VTU and
   * HDF5 writers, HDF5 itself, a plotting script): it writes to
   * temporary_name(), and commit() renames that file once the writer has
   * returned without an error. If commit() is not reached, the temporary file
   * is removed.
   */
  class StagedFile
  {
  public:
    /** A staged file for @p path (nothing is created yet). */
    explicit StagedFile(const std::string &path);

    /** Removes the temporary file if commit() was not called. */
    ~StagedFile();

    StagedFile(const StagedFile &) = delete;
    StagedFile &
    operator=(const StagedFile &) = delete;

    /** The name to give the writer. */
    const std::string &
    temporary_name() const;

    /**
     * Rename the written file to its final name. Throws an ExcMessage naming
     * the file if the writer left no file or the rename fails.
     */
    void
    commit();

  private:
    std::string final_path;
    std::string temporary;
    bool        committed = false;
  };
} // namespace masonry

#endif
