#include <masonry/core/output_file.h>

#include <deal.II/base/exceptions.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <streambuf>
#include <unistd.h>
#include <vector>

namespace masonry
{
  std::string
  temporary_file_name(const std::string &path)
  {
    const auto        slash = path.find_last_of('/');
    const std::string directory =
      slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name =
      slash == std::string::npos ? path : path.substr(slash + 1);
    const auto        dot = name.find_last_of('.');
    const std::string stem =
      dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
    const std::string extension =
      dot == std::string::npos || dot == 0 ? "" : name.substr(dot);
    return directory + "." + stem + "." + std::to_string(::getpid()) + ".part" +
           extension;
  }

  std::string
  write_error(const std::string &path, const std::string &reason)
  {
    return "cannot write '" + path + "': " + reason;
  }

  /**
   * A stream buffer on a POSIX file descriptor that remembers why the first
   * failed system call failed.
   */
  class OutputFile::Buffer : public std::streambuf
  {
  public:
    explicit Buffer(const std::string &name)
      : storage(1 << 16)
    {
      descriptor =
        ::open(name.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
      if (descriptor < 0)
        reason = std::strerror(errno);
      setp(storage.data(), storage.data() + storage.size());
    }

    ~Buffer() override
    {
      if (descriptor >= 0)
        ::close(descriptor);
    }

    /** Why the file could not be written, or "" while all went well. */
    std::string reason;

    /** Write out the buffer and close the descriptor; false on a failure. */
    bool
    finish()
    {
      flush_buffer();
      if (descriptor >= 0)
        {
          if (::close(descriptor) != 0 && reason.empty())
            reason = std::strerror(errno);
          descriptor = -1;
        }
      return reason.empty();
    }

  protected:
    int_type
    overflow(int_type c) override
    {
      if (!flush_buffer())
        return traits_type::eof();
      if (!traits_type::eq_int_type(c, traits_type::eof()))
        {
          *pptr() = traits_type::to_char_type(c);
          pbump(1);
        }
      return traits_type::not_eof(c);
    }

    int
    sync() override
    {
      return flush_buffer() ? 0 : -1;
    }

  private:
    std::vector<char> storage;
    int               descriptor = -1;

    bool
    flush_buffer()
    {
      if (!reason.empty())
        return false;
      const char *p = pbase();
      while (p < pptr())
        {
          const ssize_t n = ::write(descriptor, p, pptr() - p);
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            {
              // ENOSPC, EIO, EFBIG (a file-size limit with SIGXFSZ ignored)
              reason = n < 0 ? std::strerror(errno) : "nothing written";
              return false;
            }
          p += n;
        }
      setp(storage.data(), storage.data() + storage.size());
      return true;
    }
  };

  OutputFile::OutputFile(const std::string &path, const bool in_place)
    : std::ostream(nullptr)
    , final_path(path)
    , written_path(in_place ? path : temporary_file_name(path))
    , buffer(std::make_unique<Buffer>(written_path))
  {
    AssertThrow(buffer->reason.empty(),
                dealii::ExcMessage(write_error(path, buffer->reason)));
    rdbuf(buffer.get());
  }

  OutputFile::~OutputFile()
  {
    if (!closed)
      {
        const bool whole = buffer->finish();
        buffer.reset();
        if (written_path != final_path || !whole)
          std::remove(written_path.c_str());
      }
  }

  void
  OutputFile::close()
  {
    AssertThrow(!closed,
                dealii::ExcMessage("'" + final_path + "' closed twice"));
    flush();
    const bool  written = buffer->finish() && good();
    std::string reason  = buffer->reason;
    if (written && written_path != final_path &&
        std::rename(written_path.c_str(), final_path.c_str()) != 0)
      reason = std::strerror(errno);
    else if (!written && reason.empty())
      reason = "the stream failed";
    if (!reason.empty())
      {
        std::remove(written_path.c_str());
        closed = true;
        AssertThrow(false, dealii::ExcMessage(write_error(final_path, reason)));
      }
    closed = true;
  }

  const std::string &
  OutputFile::path() const
  {
    return final_path;
  }

  std::string
  OutputFile::error() const
  {
    if (buffer != nullptr && !buffer->reason.empty())
      return write_error(final_path, buffer->reason);
    if (!good())
      return write_error(final_path, "the stream failed");
    return {};
  }

  StagedFile::StagedFile(const std::string &path)
    : final_path(path)
    , temporary(temporary_file_name(path))
  {}

  StagedFile::~StagedFile()
  {
    if (!committed)
      std::remove(temporary.c_str());
  }

  const std::string &
  StagedFile::temporary_name() const
  {
    return temporary;
  }

  void
  StagedFile::commit()
  {
    committed = true;
    if (::access(temporary.c_str(), F_OK) != 0)
      AssertThrow(false,
                  dealii::ExcMessage(
                    write_error(final_path, "its writer left no file")));
    if (std::rename(temporary.c_str(), final_path.c_str()) != 0)
      {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        AssertThrow(false, dealii::ExcMessage(write_error(final_path, reason)));
      }
  }
} // namespace masonry
