/*
 * The real-time thread, apart from the model and the state: its own struct, its own file (roq_loop.c). It runs
 * roq_tick on the model and state it is given, 1 kHz on absolute deadlines; nothing else touches them while it
 * runs (Java meets the loop in the shared block only).
 */
#ifndef ROQ_LOOP_H
#define ROQ_LOOP_H

#include <pthread.h>
#include <stdint.h>
#include "roq_model.h"
#include "roq_state.h"

typedef struct {
    roq_model *model;             /* the thread's tick applies the model edits (roq_model_apply_edits) */
    roq_state *state;
    pthread_t thread;
    int started;
    volatile int running;
    int dma_fd;                   /* /dev/cpu_dma_latency held open while running, or -1 */
    int64_t flags;                /* RT_* bits obtained */
    int64_t period_ns;
} roq_rt;

/* Starts the thread (priority for SCHED_FIFO); warnings lists what could not be obtained. 0 or an errno. */
int roq_rt_start(roq_rt *rt, roq_model *model, roq_state *state, int priority, char *warnings, int warnings_size);
/* Stops the thread and waits for it; gives back what start took. Harmless when not started. */
void roq_rt_stop(roq_rt *rt);
/* Puts the calling thread under SCHED_FIFO at priority: the Java threads on the path from a snapshot to a command
   (the bridge, the network's workers), so a busy machine's other processes do not take their core. 0 or an errno. */
int roq_thread_fifo(int priority);
/* Counts one wake-up latency in the state's stage (histogram, maximum). */
void roq_record_latency(roq_state *state, int64_t latency_ns);

#endif
