package org.fdnet.corba;

import java.io.IOException;
import java.io.NotSerializableException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import javax.rmi.CORBA.Stub;
import javax.rmi.CORBA.StubDelegate;
import org.omg.CORBA.ORB;

/**
 * The JDK 17 fix for JacORB: its object references extend {@code javax.rmi.CORBA.Stub}, whose static
 * initialiser loads the class named by {@code javax.rmi.CORBA.StubClass}. The JDK no longer ships a
 * default, so {@link OrbRuntime} names this one. FDNet never serialises stubs or uses RMI-IIOP, so only
 * identity matters here.
 */
public final class FdnetStubDelegate implements StubDelegate {

    @Override
    public int hashCode(Stub self) {
        return System.identityHashCode(self);
    }

    @Override
    public boolean equals(Stub self, Object obj) {
        return self == obj;
    }

    @Override
    public String toString(Stub self) {
        return self.getClass().getName() + "@" + Integer.toHexString(System.identityHashCode(self));
    }

    @Override
    public void connect(Stub self, ORB orb) {
        // JacORB references are bound to their ORB when created; there is nothing to connect.
    }

    @Override
    public void readObject(Stub self, ObjectInputStream in) throws IOException {
        throw new NotSerializableException("FDNet does not serialise CORBA references with Java serialisation");
    }

    @Override
    public void writeObject(Stub self, ObjectOutputStream out) throws IOException {
        throw new NotSerializableException("FDNet does not serialise CORBA references with Java serialisation");
    }
}
