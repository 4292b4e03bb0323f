package org.fdnet.logger.soak;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.corba.FdnetChildProcess;

/**
 * Writes 1, 2, 3 … into {@code main/Seq} through the run's standard input ({@code send main/Seq=k}), one value every
 * {@code periodMillis}, and keeps the values the network acknowledged ({@code ok: send main/Seq=k}: applied on the
 * Data's home host) with the time of the acknowledgement. A refused or unanswered value is not counted.
 */
final class SequenceWriter implements Runnable {
    static final String NODE = "main/Seq";
    private static final long ANSWER_TIMEOUT_MILLIS = 15_000;

    /** One acknowledged value and when the acknowledgement came, epoch milliseconds. */
    record Acknowledged(long value, long atMillis) {
    }

    private final FdnetChildProcess run;
    private final long periodMillis;
    private final List<Acknowledged> acknowledged = new ArrayList<>();
    private volatile boolean stopping;
    private int refused;
    private int unanswered;
    private int seen;

    SequenceWriter(FdnetChildProcess run, long periodMillis) {
        this.run = run;
        this.periodMillis = periodMillis;
    }

    @Override
    public void run() {
        long next = 1;
        seen = run.output().size();
        while (!stopping) {
            long started = System.currentTimeMillis();
            run.send("send " + NODE + "=" + next);
            String answer = awaitAnswer(next);
            if (answer == null) {
                unanswered++;
            } else if (answer.startsWith("ok: ")) {
                synchronized (this) {
                    acknowledged.add(new Acknowledged(next, System.currentTimeMillis()));
                }
            } else {
                refused++;
            }
            next++;
            long left = periodMillis - (System.currentTimeMillis() - started);
            if (left > 0) {
                try {
                    Thread.sleep(left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }
    }

    /** The run's answer to value {@code k}: it answers every command with one line, in order. */
    private String awaitAnswer(long k) {
        String sent = "send " + NODE + "=" + k;
        long deadline = System.currentTimeMillis() + ANSWER_TIMEOUT_MILLIS;
        while (System.currentTimeMillis() < deadline && run.isAlive()) {
            List<String> lines = run.output();
            for (; seen < lines.size(); seen++) {
                String line = lines.get(seen);
                for (String verdict : new String[] {"ok: ", "refused: ", "error: "}) {
                    if (line.startsWith(verdict + sent) && (line.length() == (verdict + sent).length()
                            || !Character.isDigit(line.charAt((verdict + sent).length())))) {
                        seen++;
                        return line;
                    }
                }
            }
            try {
                Thread.sleep(2);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return null;
            }
        }
        return null;
    }

    void stop() {
        stopping = true;
    }

    synchronized List<Acknowledged> acknowledged() {
        return List.copyOf(acknowledged);
    }

    /** The first value acknowledged at or after {@code epochMillis}; -1 when none was. */
    synchronized long firstAcknowledgedFrom(long epochMillis) {
        for (Acknowledged a : acknowledged) {
            if (a.atMillis() >= epochMillis) {
                return a.value();
            }
        }
        return -1;
    }

    int refused() {
        return refused;
    }

    int unanswered() {
        return unanswered;
    }
}
