// Linux's SCHED_BATCH for a simulator running as fast as possible: a throughput job.
#pragma once

namespace bullet_turtlebot {

// Puts every thread of this process under SCHED_BATCH (same priority, no wake-up
// preemption). roscpp hands each message that has a subscriber (every /clock, 100 per sim
// second, once any node runs on sim time) to its poll thread; a woken thread that preempts
// the stepping thread costs two context switches per 10 ms step, more than the step.
// Unpreempted, the poll thread runs at the next slice and sends what has queued up.
// Returns false if the kernel refused (the node runs as before).
bool use_batch_scheduling();

}  // namespace bullet_turtlebot
