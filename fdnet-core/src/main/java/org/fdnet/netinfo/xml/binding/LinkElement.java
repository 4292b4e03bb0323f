package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlTransient;

/** A {@code read} or a {@code write}: one Reader or Writer connection. */
@XmlTransient
public abstract class LinkElement extends Located {
    public abstract String linkName();

    public abstract ExistElement exist();
}
