package org.fdnet.netinfo.xml;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBException;
import org.fdnet.netinfo.xml.binding.CnetElement;
import org.fdnet.netinfo.xml.binding.FdgElement;

/**
 * The two JAXB contexts, built once on first use (a context costs ~100 ms to build and is
 * thread-safe; unmarshallers and marshallers are cheap and are made per file).
 */
final class JaxbContexts {
    private JaxbContexts() {
    }

    static JAXBContext network() {
        return NetworkHolder.CONTEXT;
    }

    static JAXBContext layout() {
        return LayoutHolder.CONTEXT;
    }

    private static JAXBContext create(Class<?> root) {
        try {
            return JAXBContext.newInstance(root);
        } catch (JAXBException e) {
            throw new IllegalStateException("the JAXB bindings of " + root.getSimpleName() + " are broken", e);
        }
    }

    private static final class NetworkHolder {
        static final JAXBContext CONTEXT = create(CnetElement.class);
    }

    private static final class LayoutHolder {
        static final JAXBContext CONTEXT = create(FdgElement.class);
    }
}
