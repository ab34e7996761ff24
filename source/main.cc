/**
 * @file
 * The `masonry` executable: a launcher that links none of masonry's heavy
 * libraries. `--version`, `--help` and a call without arguments are
 * answered here (the dynamic loader's relocation of the ~200 libraries
 * behind libmasonry, deal.II, Trilinos, PETSc, OpenCASCADE, Open MPI, is
 * most of the start-up time); everything else loads libmasonry with
 * dlopen() and calls masonry_main() (MPI_Init, run_application()), or for
 * `--validate' outside mpirun masonry_validate() (no MPI_Init).
 * Measurements: contrib/benchmarks/startup.
 */
#include <masonry/config.h>
#include <masonry/core/usage.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <string>
#include <unistd.h>

namespace
{
  /** Whether this process was started by an MPI launcher. */
  bool
  under_mpi()
  {
    for (const char *name :
         {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
      if (std::getenv(name))
        return true;
    return false;
  }

  /** The directory of this executable, with a trailing slash, or "". */
  std::string
  own_directory()
  {
    char       path[PATH_MAX];
    const auto n = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
    if (n <= 0)
      return "";
    path[n]                 = '\0';
    const std::string self  = path;
    const auto        slash = self.rfind('/');
    return slash == std::string::npos ? "" : self.substr(0, slash + 1);
  }

  /**
   * OpenBLAS (the BLAS under MUMPS) picks its kernels by the
   * processor's family and model number, and takes its oldest generic
   * kernels (Prescott, SSE3) for a model it does not know: Debian 12's
   * 0.3.21 does so on processors newer than itself (family 6, model 207
   * on the development machine, which has AVX-512). This names the
   * kernels by the instruction sets the processor and the operating
   * system support: SkylakeX with AVX-512 (F, CD, BW, DQ, VL), Haswell
   * with AVX2 and FMA, otherwise OpenBLAS's own choice. Only a default:
   * a user's OPENBLAS_CORETYPE wins; another BLAS ignores it. Faster
   * factorisations, other round-off (contrib/benchmarks/wallette_cyclic/
   * results-2026-11-28c.md).
   */
  void
  choose_blas_kernels()
  {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();
    const char *kernels = nullptr;
    if (__builtin_cpu_supports("avx512f") &&
        __builtin_cpu_supports("avx512cd") &&
        __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512vl"))
      kernels = "SkylakeX";
    else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
      kernels = "Haswell";
    if (kernels)
      ::setenv("OPENBLAS_CORETYPE", kernels, 0);
#endif
  }
} // namespace

int
main(int argc, char **argv)
{
  // the answers that need no library (not under mpirun, where only rank 0
  // may print, and not with --defaults, which changes their meaning)
  bool defaults = false;
  for (int i = 1; i < argc; ++i)
    defaults = defaults || std::strcmp(argv[i], "--defaults") == 0;
  if (!defaults && !under_mpi())
    {
      if (argc == 1)
        {
          std::fputs(masonry::usage_text, stderr);
          return 2;
        }
      if (std::strcmp(argv[1], "--help") == 0 ||
          std::strcmp(argv[1], "-h") == 0)
        {
          std::fputs(masonry::usage_text, stdout);
          return 0;
        }
      if (std::strcmp(argv[1], "--version") == 0)
        {
          std::printf("masonry %s\n", MASONRY_VERSION);
          return 0;
        }
    }

  // A process not started by mpirun is an MPI singleton of one rank: Open
  // MPI need not probe its matching transport layers for it (with libpsm2
  // installed and no Omni-Path card, the psm2 layer polls for 0.2 s). Only
  // a default: a user's own setting wins. (Not ess_singleton_isolated,
  // which saves starting orted: isolated singletons share one session
  // directory, and one that ends removes it under another that starts.)
  if (!under_mpi())
    ::setenv("OMPI_MCA_pml", "ob1", 0);
  choose_blas_kernels();

  // next to the executable (build tree), in ../lib (installed), or where
  // the dynamic loader finds it; RTLD_GLOBAL for Open MPI's components.
  // RTLD_LAZY: functions of the ~200 libraries are bound when first called,
  // not all of them at load time (LD_BIND_NOW=1 restores that).
  const std::string directory = own_directory();
  void             *library   = nullptr;
  std::string       errors;
  for (const std::string &candidate : {directory + "libmasonry.so",
                                       directory + "../lib/libmasonry.so",
                                       std::string("libmasonry.so")})
    {
      library = ::dlopen(candidate.c_str(), RTLD_LAZY | RTLD_GLOBAL);
      if (library)
        break;
      errors += std::string("\n  ") + ::dlerror();
    }
  if (!library)
    {
      std::fprintf(stderr,
                   "masonry: cannot load libmasonry.so:%s\n",
                   errors.c_str());
      return 1;
    }
  // `--validate FILE' of a process not started by mpirun needs no MPI:
  // masonry_validate() checks the file without MPI_Init
  bool validate = false;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--defaults") != 0)
      {
        validate = std::strcmp(argv[i], "--validate") == 0;
        break;
      }
  validate         = validate && !under_mpi();
  using Main       = int (*)(int, char **);
  const auto entry = reinterpret_cast<Main>(
    ::dlsym(library, validate ? "masonry_validate" : "masonry_main"));
  if (!entry)
    {
      std::fprintf(stderr, "masonry: libmasonry.so has no entry point\n");
      return 1;
    }
  const int status = entry(argc, argv);
  // a check leaves nothing to clean up (no file open, no MPI): its answer
  // is written, so the process ends without the static destructors of the
  // ~200 libraries (pagmo, TBB, boost serialisation, ...), which took
  // 4-7 ms of CPU (contrib/benchmarks/startup/results-2026-11-28.md)
  if (validate)
    {
      std::fflush(nullptr);
      std::_Exit(status);
    }
  return status;
}
