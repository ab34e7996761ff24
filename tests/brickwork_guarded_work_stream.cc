/**
 * run_guarded() (source/brickwork/assembly/guarded_work_stream.h) on two
 * threads: an exception thrown by a worker reaches the caller, where
 * deal.II's WorkStream alone would print it with a stack trace and abort
 * the program, and nothing is copied once an item has failed. The
 * wallette's hostile-input test (error_wallette_hostile) met this path
 * with a unit tensile strength of 1e-300 Pa, until the splitting
 * interfaces' law derived from it was rejected before the first assembly.
 */
#include <deal.II/base/multithread_info.h>

#include <iostream>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "../source/brickwork/assembly/guarded_work_stream.h"

int
main()
{
  dealii::MultithreadInfo::set_thread_limit(2);
  std::vector<int> items(1000);
  std::iota(items.begin(), items.end(), 0);
  unsigned int copied        = 0;
  bool         failed_copied = false;
  try
    {
      masonry::brickwork::model::run_guarded(
        items.cbegin(),
        items.cend(),
        [](const std::vector<int>::const_iterator &it, int &, int &copy) {
          // (the failed item's copy is filled: it must still not be
          // copied)
          copy = *it;
          if (*it == 500)
            throw std::runtime_error("item 500 failed");
        },
        [&](const int &copy) {
          ++copied;
          failed_copied = failed_copied || copy == 500;
        },
        0,
        0);
      std::cout << "no exception reached the caller\n";
    }
  catch (const std::exception &e)
    {
      std::cout << "the caller caught: " << e.what() << '\n';
    }
  std::cout << "the failed item copied: " << (failed_copied ? "yes" : "no")
            << "\nall items copied: " << (copied == items.size() ? "yes" : "no")
            << '\n';
}
