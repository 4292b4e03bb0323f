package org.fdnet.corba.bench;

import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The Relation at the far end of {@code fdnet bench corba}'s hop: its input carries the
 * {@link System#nanoTime()} at which the value was written on another host, and it writes how long
 * ago that was. Processes on one Linux machine share the monotonic clock {@code nanoTime} reads, so the
 * difference is the one-way time from the write on host A to this Relation firing on host B.
 */
public class HopStamp extends Relation {
    @Override
    protected void compute(RelationContext context) {
        Value written = context.input(0);
        if (written == null || written.asLong() <= 0 || !context.inputChanged(0)) {
            return; // the Data's initial value, or a firing for another input: not a sample
        }
        context.outputAll(Value.of(System.nanoTime() - written.asLong()));
    }
}
