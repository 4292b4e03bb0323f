package org.fdnet.netinfo.xml.binding;

import jakarta.xml.bind.annotation.XmlAccessType;
import jakarta.xml.bind.annotation.XmlAccessorType;
import jakarta.xml.bind.annotation.XmlAttribute;
import jakarta.xml.bind.annotation.XmlElement;
import jakarta.xml.bind.annotation.XmlType;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code <module name=".." loadatstart="yes|no">}: the 2004 Module extension, extended by FDNet with the modules it
 * holds (nested modules, after its connections, so a 2004 file is unchanged).
 */
@XmlAccessorType(XmlAccessType.FIELD)
@XmlType(propOrder = {"structures", "connections", "modules"})
public class ModuleElement extends ModuleBody {
    @XmlAttribute(required = true)
    public String name;
    @XmlAttribute
    public String loadatstart;
    @XmlElement(name = "module")
    public List<ModuleElement> modules = new ArrayList<>();
}
