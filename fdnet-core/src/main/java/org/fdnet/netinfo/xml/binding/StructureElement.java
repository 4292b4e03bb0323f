package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlTransient;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code (name,host,path,class,param*)}: the body shared by {@code dstructure} and {@code pstructure}
 * (the subclasses declare the element order, since JAXB ignores it on a transient class).
 */
@XmlTransient
@XmlAccessorType(XmlAccessType.FIELD)
public abstract class StructureElement extends Located {
    public String name;
    public String host;
    public String path;
    @XmlElement(name = "class")
    public String className;
    @XmlElement(name = "param")
    public List<ParamElement> params = new ArrayList<>();
}
