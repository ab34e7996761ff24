/**
 * @file
 * One thread for deal.II while an object of this kind lives (the model's
 * assembly and deletion, and the postprocessors that compute strains with
 * FEValues).
 */
#ifndef masonry_brickwork_one_thread_h
#define masonry_brickwork_one_thread_h

#include <deal.II/base/multithread_info.h>

namespace masonry
{
  namespace brickwork
  {
    /**
     * deal.II's FEValues reuses the last cell's values for a cell that is
     * a translation of it (equal to round-off) only while one thread is
     * allowed. What feeds the solution (the cells' geometries and
     * elastic matrices, the deletion criteria) is computed under this
     * guard, so `Assembly threads' changes no number.
     */
    class OneThread
    {
    public:
      OneThread()
      {
        dealii::MultithreadInfo::set_thread_limit(1);
      }
      ~OneThread()
      {
        dealii::MultithreadInfo::set_thread_limit(threads);
      }
      OneThread(const OneThread &) = delete;
      OneThread &
      operator=(const OneThread &) = delete;

    private:
      const unsigned int threads = dealii::MultithreadInfo::n_threads();
    };
  } // namespace brickwork
} // namespace masonry

#endif
