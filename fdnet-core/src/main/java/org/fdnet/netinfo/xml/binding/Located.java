package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlTransient;
import org.glassfish.jaxb.core.annotation.XmlLocation;
import org.xml.sax.Locator;

/** An element that remembers where it stood in its file, so semantic errors can name the line. */
@XmlTransient
public abstract class Located {
    @XmlLocation
    @XmlTransient
    public Locator locator;

    public int line() {
        return locator == null ? 0 : locator.getLineNumber();
    }

    public int column() {
        return locator == null ? 0 : locator.getColumnNumber();
    }
}
