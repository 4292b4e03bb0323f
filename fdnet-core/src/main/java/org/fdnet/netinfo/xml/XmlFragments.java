package org.fdnet.netinfo.xml;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.Marshaller;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;

/** Marshals a root element as indented UTF-8 without an XML declaration (the caller writes its own header). */
final class XmlFragments {
    private XmlFragments() {
    }

    static void marshal(JAXBContext context, Object root, OutputStream out) throws JAXBException, IOException {
        Marshaller marshaller = context.createMarshaller();
        marshaller.setProperty(Marshaller.JAXB_ENCODING, "UTF-8");
        marshaller.setProperty(Marshaller.JAXB_FORMATTED_OUTPUT, Boolean.TRUE);
        marshaller.setProperty(Marshaller.JAXB_FRAGMENT, Boolean.TRUE);
        ByteArrayOutputStream buffer = new ByteArrayOutputStream();
        marshaller.marshal(root, buffer);
        byte[] bytes = buffer.toByteArray();
        // A formatted fragment starts with a line break and may lack the last one.
        int from = 0;
        while (from < bytes.length && (bytes[from] == '\n' || bytes[from] == '\r')) {
            from++;
        }
        int to = bytes.length;
        while (to > from && (bytes[to - 1] == '\n' || bytes[to - 1] == '\r')) {
            to--;
        }
        out.write(bytes, from, to - from);
        out.write('\n');
    }
}
