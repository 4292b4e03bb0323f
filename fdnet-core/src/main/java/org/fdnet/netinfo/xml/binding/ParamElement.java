package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;
import jakarta.xml.bind.annotation.XmlValue;

/** {@code <param name=".." type="..">value</param>}; both attributes are FDNet's optional extension. */
@XmlAccessorType(XmlAccessType.FIELD)
public class ParamElement extends Located {
    @XmlAttribute
    public String name;
    @XmlAttribute
    public String type;
    @XmlValue
    public String value = "";
}
