#include <masonry/core/stop_signals.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <atomic>

namespace masonry
{
  namespace
  {
    /** The signal noted (0: none); written by the handler only. */
    std::atomic<int>  noted_signal{0};
    std::atomic<bool> installed{false};

    extern "C" void
    note_signal(const int signal)
    {
      if (noted_signal.load() == signal)
        {
          // the second one: end the process as without a handler
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      noted_signal.store(signal);
    }
  } // namespace

  StopSignals::StopSignals()
  {
    AssertThrow(!installed.exchange(true),
                dealii::ExcMessage("StopSignals: one object at a time"));
    noted_signal.store(0);
    struct sigaction action = {};
    action.sa_handler       = note_signal;
    sigemptyset(&action.sa_mask);
    // a system call interrupted by the signal is restarted: the run goes on
    // to its next safe point undisturbed
    action.sa_flags = SA_RESTART;
    sigaction(SIGTERM, &action, &previous_term);
    sigaction(SIGINT, &action, &previous_int);
  }

  StopSignals::~StopSignals()
  {
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGINT, &previous_int, nullptr);
    installed.store(false);
  }

  int
  StopSignals::received(const MPI_Comm comm) const
  {
    return dealii::Utilities::MPI::max(noted_signal.load(), comm);
  }

  std::string
  StopSignals::name(const int signal)
  {
    if (signal == SIGTERM)
      return "SIGTERM";
    if (signal == SIGINT)
      return "SIGINT";
    return "signal " + std::to_string(signal);
  }
} // namespace masonry
