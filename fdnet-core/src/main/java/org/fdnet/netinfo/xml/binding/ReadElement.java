package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlType;

/**
 * {@code read (name?,(data|dstructure),(proc|pstructure),exist?)}: a Reader. Either end may be a
 * reference by name or a node declared right here.
 */
@XmlAccessorType(XmlAccessType.FIELD)
@XmlType(propOrder = {"name", "data", "dstructure", "proc", "pstructure", "exist"})
public class ReadElement extends LinkElement {
    public String name;
    public LocatedText data;
    public DStructureElement dstructure;
    public LocatedText proc;
    public PStructureElement pstructure;
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
