// run_pagmo() in libmasonry: loads libmasonry_pagmo.so (pagmo, the island
// loop and the built-in algorithms' factories) on the first call and hands
// the run to it, so that a process that adapts nothing never loads pagmo
// (see pagmo_runner.h). No pagmo header here.
#include <masonry/adaptation/pagmo_runner.h>

#include <dlfcn.h>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>

namespace masonry
{
  namespace adaptation
  {
    namespace
    {
      using Entry = void (*)(const MPI_Comm,
                             const PagmoSettings &,
                             const std::vector<Fitness> &,
                             const std::vector<double> &,
                             const std::function<void(const Generation &)> &,
                             Result &,
                             std::exception_ptr &);

      /**
       * libmasonry_pagmo.so's entry point, the library loaded on the first
       * call: from the directory of libmasonry.so (build tree and installed
       * lib/), else wherever the dynamic loader finds it.
       */
      Entry
      entry()
      {
        static std::once_flag once;
        static Entry          function = nullptr;
        static std::string    errors;
        std::call_once(once, []() {
          std::string directory;
          Dl_info     info;
          if (::dladdr(reinterpret_cast<void *>(&entry), &info) != 0 &&
              info.dli_fname != nullptr)
            {
              directory = info.dli_fname;
              directory.erase(directory.find_last_of('/') + 1);
            }
          for (const std::string &candidate :
               {directory + "libmasonry_pagmo.so",
                std::string("libmasonry_pagmo.so")})
            {
              void *library =
                ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
              if (library == nullptr)
                {
                  errors += std::string("; ") + ::dlerror();
                  continue;
                }
              function =
                reinterpret_cast<Entry>(::dlsym(library, "masonry_pagmo_run"));
              if (function != nullptr)
                return;
              errors += "; " + candidate + " has no masonry_pagmo_run";
            }
        });
        if (function == nullptr)
          throw std::runtime_error(
            "cannot load libmasonry_pagmo.so, the library of the pagmo "
            "optimisers" +
            errors);
        return function;
      }
    } // namespace

    Result
    run_pagmo(const MPI_Comm                                 comm,
              const PagmoSettings                           &settings,
              const std::vector<Fitness>                    &fitness,
              const std::vector<double>                     &x0,
              const std::function<void(const Generation &)> &progress)
    {
      Result             result;
      std::exception_ptr error;
      entry()(comm, settings, fitness, x0, progress, result, error);
      if (error)
        std::rethrow_exception(error);
      return result;
    }
  } // namespace adaptation
} // namespace masonry
