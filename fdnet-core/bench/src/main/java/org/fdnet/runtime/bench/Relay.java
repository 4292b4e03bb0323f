package org.fdnet.runtime.bench;

import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/** The benchmark's unit of work: reads one number, writes it plus one to every output. */
public final class Relay extends Relation {
    @Override
    protected void compute(RelationContext context) {
        context.outputAll(Value.of(context.input(0).asDouble() + 1));
    }
}
