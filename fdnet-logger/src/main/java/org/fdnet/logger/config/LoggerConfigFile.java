package org.fdnet.logger.config;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;

/**
 * The configuration file: Java properties, one line per {@link LoggerSetting} key. A missing file means
 * the defaults (as in the thesis: the panel starts from defaults and saves what the user enters).
 */
public final class LoggerConfigFile {
    private LoggerConfigFile() {
    }

    public static Path defaultPath() {
        return Path.of(System.getProperty("user.home"), ".fdnet", "logger.properties");
    }

    /** Reads the file into a config; a bad value fails naming the file and the key. */
    public static LoggerConfig load(Path file) throws IOException {
        LoggerConfig config = new LoggerConfig();
        if (!Files.exists(file)) {
            return config;
        }
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(r);
        }
        for (String key : p.stringPropertyNames()) {
            try {
                config.set(LoggerSetting.ofKey(key), p.getProperty(key));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
            }
        }
        try {
            config.validate();
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
        }
        return config;
    }

    public static void save(LoggerConfig config, Path file) throws IOException {
        Properties p = new Properties();
        for (LoggerSetting s : LoggerSetting.values()) {
            p.setProperty(s.key(), config.get(s));
        }
        if (file.getParent() != null) {
            Files.createDirectories(file.getParent());
        }
        try (Writer w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            p.store(w, "FDNet logger configuration (fdnet logger --config FILE); see docs/reference/logger.md");
        }
    }
}
