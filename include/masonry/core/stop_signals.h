/**
 * @file
 * SIGTERM and SIGINT as a request to stop at the next safe point: a batch
 * system's time limit or Ctrl-C then ends a long run with its results and a
 * checkpoint written instead of killing it mid-step.
 */
#ifndef masonry_core_stop_signals_h
#define masonry_core_stop_signals_h

#include <deal.II/base/mpi.h>

#include <csignal>
#include <string>

namespace masonry
{
  /**
   * While an object of this class lives, SIGTERM and SIGINT do not end the
   * process but are noted; the analysis asks received() at its safe points
   * (between steps) and stops there. A second signal of the same kind ends
   * the process as before (a user who presses Ctrl-C twice means it). The
   * previous handlers come back when the object is destroyed. One object at
   * a time.
   */
  class StopSignals
  {
  public:
    StopSignals();
    ~StopSignals();

    StopSignals(const StopSignals &) = delete;
    StopSignals &
    operator=(const StopSignals &) = delete;

    /**
     * The signal that any rank of @p comm received (SIGTERM or SIGINT), or
     * 0. Collective: every rank must call it at the same point, and all get
     * the same answer, so that the ranks stop together.
     */
    int
    received(const MPI_Comm comm) const;

    /** "SIGTERM", "SIGINT" or "signal N". */
    static std::string
    name(const int signal);

  private:
    struct sigaction previous_term;
    struct sigaction previous_int;
  };
} // namespace masonry

#endif
