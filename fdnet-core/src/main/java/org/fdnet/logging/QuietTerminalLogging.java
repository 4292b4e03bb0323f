package org.fdnet.logging;

import org.slf4j.ILoggerFactory;
import org.slf4j.IMarkerFactory;
import org.slf4j.helpers.BasicMarkerFactory;
import org.slf4j.helpers.NOPMDCAdapter;
import org.slf4j.spi.MDCAdapter;
import org.slf4j.spi.SLF4JServiceProvider;

/**
 * The SLF4J provider of the {@code fdnet} command: warnings to the terminal, details to a log file (see the
 * package description). Settings (system properties): {@code fdnet.logFile} (default
 * {@code ~/.fdnet/logs/fdnet-<time>-<pid>.log}), {@code fdnet.logLevel} ({@code info} or {@code debug}).
 */
public final class QuietTerminalLogging implements SLF4JServiceProvider {
    private final IMarkerFactory markers = new BasicMarkerFactory();
    private final MDCAdapter mdc = new NOPMDCAdapter();
    private ILoggerFactory factory;

    /** Makes this the process's SLF4J provider; call before anything asks for a logger. */
    public static void select() {
        if (System.getProperty("slf4j.provider") == null) {
            System.setProperty("slf4j.provider", QuietTerminalLogging.class.getName());
            System.setProperty("slf4j.internal.verbosity", "WARN");
        }
    }

    @Override
    public ILoggerFactory getLoggerFactory() {
        return factory;
    }

    @Override
    public IMarkerFactory getMarkerFactory() {
        return markers;
    }

    @Override
    public MDCAdapter getMDCAdapter() {
        return mdc;
    }

    @Override
    public String getRequestedApiVersion() {
        return "2.0.99";
    }

    @Override
    public void initialize() {
        LogRouting routing = LogRouting.fromSystemProperties();
        factory = name -> new RoutedLogger(name, routing);
    }
}
