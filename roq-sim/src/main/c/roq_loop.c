/*
 * The real-time thread: 1 kHz on absolute deadlines (clock_nanosleep TIMER_ABSTIME), SCHED_FIFO, mlockall and
 * /dev/cpu_dma_latency = 0 when permitted. Per period: sleep, measure the wake-up latency, run one tick, count an
 * overrun when the tick ends after the next deadline. The only system call in the loop is the sleep
 * (clock_gettime is served by the vDSO). The thread's own struct is roq_rt (roq_loop.h); it ticks the model and
 * state it was started with and nothing else.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <sched.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <time.h>
#include <unistd.h>
#include "roq_loop.h"
#include "roq_sim.h"

#define NS_PER_S 1000000000LL

static int64_t ns(const struct timespec *t) {
    return (int64_t)t->tv_sec * NS_PER_S + t->tv_nsec;
}

static void set_ns(struct timespec *t, int64_t v) {
    t->tv_sec = v / NS_PER_S;
    t->tv_nsec = v % NS_PER_S;
}

void roq_record_latency(roq_state *s, int64_t latency_ns) {
    unsigned char *st = s->stage;
    int64_t bin = latency_ns / 1000;
    if (bin < 0) {
        bin = 0;
    }
    if (bin >= ROQ_HISTOGRAM_BINS) {
        bin = ROQ_HISTOGRAM_BINS - 1;
    }
    BLK_I(st, T_HISTOGRAM)[bin]++;
    s->histogram_bin = (int)bin;
    (*BLK_L(st, T_LATENCY_SAMPLES))++;
    if (latency_ns > *BLK_L(st, T_MAX_LATENCY_NS)) {
        *BLK_L(st, T_MAX_LATENCY_NS) = latency_ns;
    }
}

static void *loop(void *arg) {
    roq_rt *rt = arg;
    roq_state *s = rt->state;
    prctl(PR_SET_TIMERSLACK, 1UL, 0, 0, 0);
    struct timespec now, deadline;
    clock_gettime(CLOCK_MONOTONIC, &now);
    int64_t next = ns(&now) + rt->period_ns;
    while (__atomic_load_n(&rt->running, __ATOMIC_ACQUIRE)) {
        set_ns(&deadline, next);
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, NULL);
        clock_gettime(CLOCK_MONOTONIC, &now);
        int64_t woke = ns(&now);
        roq_record_latency(s, woke - next);
        roq_tick(rt->model, s);
        clock_gettime(CLOCK_MONOTONIC, &now);
        int64_t end = ns(&now);
        if (end - woke > *BLK_L(s->stage, T_MAX_TICK_NS)) {
            *BLK_L(s->stage, T_MAX_TICK_NS) = end - woke; /* published with the next tick */
        }
        next += rt->period_ns;
        if (end > next) {
            unsigned char *st = s->stage;
            (*BLK_L(st, T_OVERRUNS))++;
            if (end - next > *BLK_L(st, T_MAX_OVERRUN_NS)) {
                *BLK_L(st, T_MAX_OVERRUN_NS) = end - next;
            }
            while (next < end) { /* missed deadlines are skipped, not caught up in a burst */
                next += rt->period_ns;
            }
        }
    }
    return NULL;
}

int roq_thread_fifo(int priority) {
    struct sched_param sp = {.sched_priority = priority};
    return pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp);
}

static void warn(char *warnings, int size, const char *what, int err) {
    size_t used = strlen(warnings);
    snprintf(warnings + used, (size_t)size - used, "%s%s (%s)", used ? ", " : "", what, strerror(err));
}

int roq_rt_start(roq_rt *rt, roq_model *model, roq_state *state, int priority, char *warnings, int warnings_size) {
    int64_t flags = 0;
    warnings[0] = 0;
    rt->model = model;
    rt->state = state;
    rt->period_ns = 1000000;
    if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
        flags |= RT_MLOCKALL;
    } else {
        warn(warnings, warnings_size, "mlockall", errno);
    }
    rt->dma_fd = open("/dev/cpu_dma_latency", O_RDWR);
    if (rt->dma_fd >= 0) {
        int32_t zero = 0;
        if (write(rt->dma_fd, &zero, sizeof zero) == sizeof zero) {
            flags |= RT_DMA_LATENCY;
        } else {
            warn(warnings, warnings_size, "/dev/cpu_dma_latency", errno);
            close(rt->dma_fd);
            rt->dma_fd = -1;
        }
    } else {
        warn(warnings, warnings_size, "/dev/cpu_dma_latency", errno);
    }
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setinheritsched(&attr, PTHREAD_EXPLICIT_SCHED);
    pthread_attr_setschedpolicy(&attr, SCHED_FIFO);
    struct sched_param sp = {.sched_priority = priority};
    pthread_attr_setschedparam(&attr, &sp);
    __atomic_store_n(&rt->running, 1, __ATOMIC_RELEASE);
    int rc = pthread_create(&rt->thread, &attr, loop, rt);
    pthread_attr_destroy(&attr);
    if (rc == 0) {
        flags |= RT_SCHED_FIFO;
    } else {
        warn(warnings, warnings_size, "SCHED_FIFO", rc);
        rc = pthread_create(&rt->thread, NULL, loop, rt);
        if (rc != 0) { /* no thread at all: give back what was taken */
            __atomic_store_n(&rt->running, 0, __ATOMIC_RELEASE);
            if (rt->dma_fd >= 0) {
                close(rt->dma_fd);
                rt->dma_fd = -1;
            }
            if (flags & RT_MLOCKALL) {
                munlockall();
            }
            return rc;
        }
    }
    pthread_setname_np(rt->thread, "roq-joint-loop");
    rt->flags = flags;
    *BLK_L(state->stage, T_RT_FLAGS) = flags; /* published with the next tick */
    rt->started = 1;
    return 0;
}

void roq_rt_stop(roq_rt *rt) {
    if (!rt->started) {
        return;
    }
    __atomic_store_n(&rt->running, 0, __ATOMIC_RELEASE);
    pthread_join(rt->thread, NULL);
    rt->started = 0;
    if (rt->dma_fd >= 0) {
        close(rt->dma_fd);
        rt->dma_fd = -1;
    }
    if (rt->flags & RT_MLOCKALL) {
        munlockall();
    }
}
