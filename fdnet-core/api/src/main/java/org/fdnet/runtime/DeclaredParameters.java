package org.fdnet.runtime;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.netinfo.Parameter;

/**
 * Every parameter a node class declares: its {@code static final} {@link ParameterSpec} fields and those of its
 * superclasses ({@link Relation#PERIOD}, {@link Relation#ON_INPUT}, {@link Relation#TRIGGERS} on every Relation,
 * {@link Data#INITIAL} on every Data). A class's own declarations come first, in the order it declares them; a
 * declaration of a name hides a superclass's declaration of the same name, so a class can narrow one
 * ({@code static final ParameterSpec<Long> PERIOD = Relation.PERIOD.range(0, 0)} refuses a period).
 *
 * <p>Reading the fields initialises the class. The engine {@link #check}s a node's parameters against its class's
 * declarations before {@code init}, so a bad value is refused even when {@code init} would not read it; the tools list
 * them ({@code fdnet info --params}, the editor's node form).
 */
public final class DeclaredParameters {
    private static final ClassValue<DeclaredParameters> OF_CLASS = new ClassValue<>() {
        @Override
        protected DeclaredParameters computeValue(Class<?> type) {
            return new DeclaredParameters(type);
        }
    };

    private final Class<?> nodeClass;
    private final Map<String, ParameterSpec<?>> byName = new LinkedHashMap<>();

    private DeclaredParameters(Class<?> nodeClass) {
        this.nodeClass = nodeClass;
        for (Class<?> c = nodeClass; c != null && c != Object.class; c = c.getSuperclass()) {
            for (Field f : c.getDeclaredFields()) {
                if (Modifier.isStatic(f.getModifiers()) && ParameterSpec.class.isAssignableFrom(f.getType())) {
                    ParameterSpec<?> spec = read(f);
                    if (spec != null) {
                        byName.putIfAbsent(spec.name(), spec);
                    }
                }
            }
        }
    }

    private static ParameterSpec<?> read(Field f) {
        if (!f.trySetAccessible()) {
            throw new IllegalStateException("the parameter declaration " + f.getDeclaringClass().getName() + "."
                    + f.getName() + " cannot be read: declare it public");
        }
        try {
            return (ParameterSpec<?>) f.get(null);
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("the parameter declaration " + f + " cannot be read", e);
        }
    }

    /**
     * The declarations of a node class (found once per class).
     *
     * @param nodeClass a Data or Relation class
     * @return its declared parameters
     */
    public static DeclaredParameters of(Class<?> nodeClass) {
        return OF_CLASS.get(nodeClass);
    }

    /**
     * The class these declarations belong to.
     *
     * @return the node class
     */
    public Class<?> nodeClass() {
        return nodeClass;
    }

    /**
     * Every declaration: the class's own first, then its superclasses'.
     *
     * @return the declarations, in that order
     */
    public List<ParameterSpec<?>> all() {
        return List.copyOf(byName.values());
    }

    /**
     * The declaration of one parameter.
     *
     * @param name the parameter's name
     * @return the declaration, or {@code null} when the class declares no such parameter
     */
    public ParameterSpec<?> find(String name) {
        return byName.get(name);
    }

    /**
     * Checks every declared parameter: each given one parses and lies in its range, each required one is given.
     *
     * @param parameters a node's parameters
     * @throws ParameterException for the first one that fails, naming module, node, parameter and what it must be
     */
    public void check(NodeParameters parameters) {
        for (ParameterSpec<?> spec : byName.values()) {
            spec.read(parameters);
        }
    }

    /**
     * The named parameters a node gives that its class does not declare (a misspelt name, or a class that declares
     * nothing).
     *
     * @param parameters a node's parameters
     * @return their names, in file order
     */
    public List<String> undeclared(NodeParameters parameters) {
        List<String> names = new ArrayList<>();
        for (Parameter p : parameters.all()) {
            if (p.name() != null && !p.name().isEmpty() && !byName.containsKey(p.name())) {
                names.add(p.name());
            }
        }
        return names;
    }
}
