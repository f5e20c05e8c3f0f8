#include <ltn/base/blas_threads.h>

#include <dlfcn.h>

namespace ltn
{
  void
  use_one_blas_thread()
  {
    // Looked up at run time: the BLAS behind libblas.so is chosen by
    // Debian's alternatives, and only OpenBLAS has this function.
    using SetThreads = void (*)(int);
    if (const auto set_threads = reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set_threads(1);
  }
} // namespace ltn
