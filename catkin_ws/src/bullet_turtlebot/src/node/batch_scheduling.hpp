// Linux's SCHED_BATCH for a simulator running as fast as possible: a throughput job.
#pragma once

namespace bullet_turtlebot {

// Puts every thread of this process under SCHED_BATCH (same priority, no wake-up
// preemption). Under use_sim_time roscpp delivers each /clock message the node publishes to
// the node itself, on its own internal thread; a woken thread that preempts the stepping
// thread costs two context switches per 10 ms step, more than the step. Unpreempted, the
// internal thread runs at the next slice and its one-message queue takes the newest time.
// Returns false if the kernel refused (the node runs as before).
bool use_batch_scheduling();

}  // namespace bullet_turtlebot
