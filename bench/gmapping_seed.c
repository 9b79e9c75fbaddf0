// Preloaded into the real slam_gmapping by bench_slam_peers (LD_PRELOAD): time() returns
// $GMAPPING_SEED. The node has no seed parameter; it seeds its random numbers (srand48, via
// GMapping::sampleGaussian) with time(NULL) in its constructor, its only call of time() (ROS
// and log4cxx read the clock through clock_gettime and gettimeofday). Without this, runs
// started in the same wall-clock second (bench_slam_peers --jobs 2) are one draw, and no run
// can be repeated. Without GMAPPING_SEED, time() is libc's.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdlib.h>
#include <time.h>

time_t time(time_t *out) {
  const char *seed = getenv("GMAPPING_SEED");
  time_t value;
  if (seed != NULL && *seed != '\0') {
    value = (time_t)strtoll(seed, NULL, 10);
    if (out != NULL) *out = value;
    return value;
  }
  time_t (*libc_time)(time_t *) = (time_t (*)(time_t *))dlsym(RTLD_NEXT, "time");
  return libc_time(out);
}
