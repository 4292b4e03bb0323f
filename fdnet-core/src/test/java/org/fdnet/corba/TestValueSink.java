package org.fdnet.corba;

import org.fdnet.corba.idl.UnknownLink;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueSinkPOA;

/** A test's receiving end of a link: a value sent ahead is delivered like any other, its refusal dropped. */
abstract class TestValueSink extends ValueSinkPOA {
    @Override
    public void deliverAhead(ValueBatch batch) {
        try {
            deliver(batch);
        } catch (UnknownLink e) {
            // a one-way call has no reply to carry it: the confirming deliver reports it
        }
    }
}
