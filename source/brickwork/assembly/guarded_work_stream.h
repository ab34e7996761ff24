/**
 * @file
 * deal.II's WorkStream with the workers' exceptions brought back to the
 * calling thread.
 */
#ifndef masonry_brickwork_model_guarded_work_stream_h
#define masonry_brickwork_model_guarded_work_stream_h

#include <deal.II/base/work_stream.h>

#include <atomic>
#include <exception>
#include <mutex>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /**
       * WorkStream::run(begin, end, worker, copier, scratch, copy), except
       * that an exception thrown by @p worker (a law that rejects its
       * parameters at a point, a failed allocation) is rethrown here, in
       * the calling thread, after the stream has ended. deal.II catches
       * an exception of a worker thread itself, prints it with a stack
       * trace and aborts the program; rethrown, it reaches the user as the
       * same one-line error as one thrown outside the threads. After the
       * first failure the remaining items are skipped and nothing more is
       * copied (the caller gets the exception, not a partial result).
       */
      template <typename Iterator,
                typename End,
                typename Worker,
                typename Copier,
                typename Scratch,
                typename Copy>
      void
      run_guarded(const Iterator &begin,
                  const End      &end,
                  const Worker   &worker,
                  const Copier   &copier,
                  const Scratch  &scratch,
                  const Copy     &copy)
      {
        std::exception_ptr first;
        std::mutex         mutex;
        std::atomic<bool>  failed{false};
        dealii::WorkStream::run(
          begin,
          Iterator(end),
          [&](const Iterator &item, Scratch &s, Copy &c) {
            if (failed.load())
              return;
            try
              {
                worker(item, s, c);
              }
            catch (...)
              {
                const std::lock_guard<std::mutex> lock(mutex);
                if (!first)
                  first = std::current_exception();
                failed.store(true);
              }
          },
          [&](const Copy &c) {
            if (!failed.load())
              copier(c);
          },
          scratch,
          copy);
        if (first)
          std::rethrow_exception(first);
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
