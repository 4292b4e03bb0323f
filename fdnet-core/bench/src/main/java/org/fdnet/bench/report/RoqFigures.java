package org.fdnet.bench.report;

import static org.fdnet.bench.report.FigureSpec.of;

import java.util.List;

/** The report's runs of {@code bench roq}, one per part, and what it reads from each part's summary lines. */
final class RoqFigures {
    private static final String NUM = "([0-9][0-9,]*(?:\\.[0-9]+)?)";
    private static final String NETWORK = "^with the network as it is: ";
    private static final String UNPROBED = "^baseline, module Probing unloaded: ";

    static final ReportedBenchmark AB = new ReportedBenchmark("roq-ab",
            List.of("bench", "roq", "--part", "ab", "--seconds", "30", "--pushes", "30", "--drops", "10",
                    "--echo-seconds", "10"),
            List.of("bench", "roq", "--part", "ab", "--seconds", "3", "--test-seconds", "5", "--pushes", "5", "--drops", "2",
                    "--echo-seconds", "2"),
            900, List.of(
            of("roq (a): a 40 s robot test on the test kit, roq-rubble on rubble:12", "× real time",
                    "^robot test \\(SimulatedRoq\\)\\s+" + NUM + "× real time",
                    "^baseline: plant alone, same course\\s+" + NUM + "× real time",
                    Target.atLeast(10), false, "the stepped network and plant on a shared core"),
            of("roq (a): stepped network + plant, crossing", "sim s/s",
                    "^network \\+ plant \\(stepped bridge\\)\\s+" + NUM + " sim s per wall s",
                    "^baseline: plant alone\\s+" + NUM + " sim s per wall s",
                    Target.ratioAtLeast(0.8), false, "the network's firings per tick on a shared core"),
            of("roq (b): tilt reflex, stimulus → applied command, p99", "ms",
                    "^tilt reflex p99: pushes [0-9]+ ms, drops [0-9]+ ms, both together " + NUM + " ms",
                    "echo baseline p99 " + NUM + " ms",
                    Target.atMost(2), true, "pushes that land while the last brace still holds")));

    static final ReportedBenchmark PUSH = new ReportedBenchmark("roq-push",
            List.of("bench", "roq", "--part", "push", "--directions", "0,90,180", "--offsets", "0"),
            List.of("bench", "roq", "--part", "push", "--directions", "0", "--offsets", "0"),
            900, List.of(
            of("roq push: largest push survived, full network / Balance and Reflex unloaded, smallest over directions",
                    "×", "^every: ratio full / unloaded smallest " + NUM + "×", null,
                    Target.atLeast(1.5), false, "sideways and mid-swing pushes that slide RoQ across the floor")));

    static final ReportedBenchmark HEADING = new ReportedBenchmark("roq-heading",
            List.of("bench", "roq", "--part", "heading", "--seeds", "2004", "--noise", "1-4"),
            List.of("bench", "roq", "--part", "heading", "--seeds", "12", "--heading-seconds", "10", "--noise", "1"),
            900, List.of(
            of("roq heading: off the course line with module Course (without it: baseline)", "m",
                    "^\\s+[0-9]+\\s+[0-9.]+ / [0-9.]+ m\\s+" + NUM + " / ",
                    "^\\s+[0-9]+\\s+[0-9.]+ / [0-9.]+ m\\s+[0-9.]+ / " + NUM + " m",
                    null, true, "")));

    static final ReportedBenchmark BREAKTHROUGHS = new ReportedBenchmark("roq-breakthroughs",
            List.of("bench", "roq", "--part", "breakthroughs", "--noise", "1-6"),
            List.of("bench", "roq", "--part", "breakthroughs", "--noise", "1", "--sweep-seconds", "10"),
            1200, List.of(
            of("roq crossing: fragile cells broken under a loaded foot (module Probing unloaded: baseline)", "breakthroughs",
                    NETWORK + NUM + " loaded-foot breakthroughs", UNPROBED + NUM + " loaded-foot breakthroughs",
                    Target.atMost(0), true, "a foothold probed on a crust's edge holds the probe but not three feet's load"),
            of("roq crossing: walked per run, mean (module Probing unloaded: baseline)", "m",
                    NETWORK + ".*walked " + NUM + " m on average", UNPROBED + ".*walked " + NUM + " m on average",
                    Target.atLeast(4), false, "probing stops at each foothold"),
            of("roq crossing: runs that fell", "falls",
                    NETWORK + ".*probes, " + NUM + " fallen", null,
                    Target.atMost(0), true, "a fall on the crossing course")));

    private RoqFigures() {
    }
}
