package org.fdnet.testkit;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * The network file a {@link TestNetwork} parameter is started from: a {@code .fdn} path relative to the directory
 * the tests run in (Maven's: the project's folder), or absolute. Its Relations' class paths are resolved as
 * {@code fdnet run} resolves them.
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.PARAMETER)
public @interface NetworkFile {
    /** The {@code .fdn} file. */
    String value();
}
