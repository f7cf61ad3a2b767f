#include "cl/quirks.h"

#include <cstdlib> // for setenv, getenv

#ifdef __linux__
#include <sched.h>  // for sched_getaffinity, CPU_ISSET
#include <unistd.h> // for sysconf
#endif

namespace meshpaint {

namespace {

//! Whether this process may run on every online CPU, numbered 0..n-1: then
//! pinning PoCL's worker i to CPU i (what POCL_AFFINITY does, with no regard
//! for the CPUs allowed) keeps one worker on each.
bool runs_on_every_cpu()
{
#ifdef __linux__
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0)
    return false;
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  if (online < 1 || online > CPU_SETSIZE || CPU_COUNT(&allowed) != online)
    return false;
  for (long cpu = 0; cpu < online; ++cpu)
    if (!CPU_ISSET(cpu, &allowed))
      return false;
  return true;
#else
  return false;
#endif
}

} // namespace

void apply_runtime_quirks()
{
  // PoCL reads these once, when the ICD loader first initialises it;
  // setenv's last argument 0 leaves a user's own choice in place.
  setenv("POCL_KERNEL_CACHE", "1", 0);
  // A brush step is a chain of short kernels with the host waiting between
  // them: with pinned workers, small steps ran shorter and steadier
  // (docs/benchmarks.md). Only where PoCL starts a worker per CPU (no
  // POCL_MAX_PTHREAD_COUNT) and every CPU is ours: a process confined to
  // some CPUs would otherwise have its workers pinned outside them.
  if (!std::getenv("POCL_MAX_PTHREAD_COUNT") && runs_on_every_cpu())
    setenv("POCL_AFFINITY", "1", 0);
}

} // namespace meshpaint
