package org.fdnet.logging;

import org.slf4j.Marker;
import org.slf4j.event.Level;
import org.slf4j.helpers.LegacyAbstractLogger;
import org.slf4j.helpers.MessageFormatter;

/** One named SLF4J logger of the {@code fdnet} command: formats the message and hands it to {@link LogRouting}. */
final class RoutedLogger extends LegacyAbstractLogger {
    private static final long serialVersionUID = 1L;
    private final transient LogRouting routing;

    RoutedLogger(String name, LogRouting routing) {
        this.name = name;
        this.routing = routing;
    }

    @Override
    public boolean isTraceEnabled() {
        return false;
    }

    @Override
    public boolean isDebugEnabled() {
        return routing.enabled(Level.DEBUG);
    }

    @Override
    public boolean isInfoEnabled() {
        return routing.enabled(Level.INFO);
    }

    @Override
    public boolean isWarnEnabled() {
        return true;
    }

    @Override
    public boolean isErrorEnabled() {
        return true;
    }

    @Override
    protected String getFullyQualifiedCallerName() {
        return null;
    }

    @Override
    protected void handleNormalizedLoggingCall(Level level, Marker marker, String pattern, Object[] arguments,
                                               Throwable throwable) {
        routing.write(level, name, MessageFormatter.basicArrayFormat(pattern, arguments), throwable);
    }
}
