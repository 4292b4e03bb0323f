package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;

/** {@code <node name=".." x=".." y=".." width=".." height=".." colour=".."/>} of a .fdg file. */
@XmlAccessorType(XmlAccessType.FIELD)
public class FdgNodeElement extends Located {
    @XmlAttribute(required = true)
    public String name;
    @XmlAttribute(required = true)
    public String x;
    @XmlAttribute(required = true)
    public String y;
    @XmlAttribute
    public String width;
    @XmlAttribute
    public String height;
    @XmlAttribute
    public String colour;
}
