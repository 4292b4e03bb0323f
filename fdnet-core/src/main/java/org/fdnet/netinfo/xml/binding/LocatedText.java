package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlValue;

/** A text-only element ({@code data}, {@code proc}) that knows its line, for "no such node" errors. */
@XmlAccessorType(XmlAccessType.FIELD)
public class LocatedText extends Located {
    @XmlValue
    public String text = "";

    public LocatedText() {
    }

    public LocatedText(String text) {
        this.text = text;
    }
}
