package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlType;

/** {@code write (name?,data,proc,exist?)}: a Writer; both ends are references. */
@XmlAccessorType(XmlAccessType.FIELD)
@XmlType(propOrder = {"name", "data", "proc", "exist"})
public class WriteElement extends LinkElement {
    public String name;
    public LocatedText data;
    public LocatedText proc;
    @XmlElement(name = "exist")
    public ExistElement exist;

    @Override
    public String linkName() {
        return name;
    }

    @Override
    public ExistElement exist() {
        return exist;
    }
}
