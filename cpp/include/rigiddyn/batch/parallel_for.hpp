// A minimal thread pool for batches of independent tasks (batch/simulate_batch.hpp): std::threads started
// for one call and joined at its end, tasks handed out in increasing order by an atomic counter, the
// calling thread working as one of them. No shared mutable state is handed to the tasks: each task
// writes only what its index owns.
#pragma once
#include <cstddef>
#include <functional>

namespace rigiddyn {

// Number of hardware threads (std::thread::hardware_concurrency(), at least 1).
int default_thread_count();

// Runs task(k, worker) for every k in [0, n_tasks) on `threads` threads: worker 0 is the calling thread,
// workers 1 .. threads-1 are std::threads started here (no more than n_tasks - 1 of them; fewer if the
// system refuses more). Tasks are taken
// in increasing k from an atomic counter, so a worker that finishes early takes the next one. threads >= 1
// (std::invalid_argument "threads: expected ..., got ..." otherwise; checked before anything runs).
// An exception thrown by a task is kept (the one of the lowest k) and rethrown after every thread has
// joined; the other tasks still run (one task's failure never stops the others).
// `wait`, if set, is called by the calling thread alone, about every `wait_interval_ms` milliseconds while
// it waits for the other workers once no task is left (a progress report, an interrupt check); an
// exception it throws is kept as task 0's would be.
void parallel_for(std::size_t n_tasks, int threads, const std::function<void(std::size_t k, int worker)>& task,
                  const std::function<void()>& wait = {}, int wait_interval_ms = 10);

}  // namespace rigiddyn
