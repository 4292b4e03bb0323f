package org.fdnet.corba.control;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where a run on this machine says how to reach its control object: {@code ~/.fdnet/run/NAME.ref}, one line
 * with the object's address ({@code corbaloc::…} or {@code IOR:…}) and one with the run's process id. Written
 * when the run publishes, removed when it stops (only if it is still this run's), read by {@code --attach NAME}.
 */
public final class RunFiles {
    private static final Logger LOG = LoggerFactory.getLogger(RunFiles.class);
    /** Overrides the folder (tests use a temporary one); else {@code ~/.fdnet/run}. */
    public static final String FOLDER_PROPERTY = "fdnet.run.dir";

    private RunFiles() {
    }

    public static Path folder() {
        String override = System.getProperty(FOLDER_PROPERTY);
        return override != null ? Path.of(override) : Path.of(System.getProperty("user.home"), ".fdnet", "run");
    }

    /** The file of network {@code name}; characters a file name should not have become '_'. */
    public static Path fileOf(String name) {
        return folder().resolve(name.replaceAll("[^A-Za-z0-9._-]", "_") + ".ref");
    }

    public static Path write(String name, String address) throws IOException {
        Path file = fileOf(name);
        Files.createDirectories(file.getParent());
        Path tmp = Files.createTempFile(file.getParent(), ".ref", ".tmp");
        Files.writeString(tmp, address + "\n" + ProcessHandle.current().pid() + "\n", StandardCharsets.UTF_8);
        Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        return file;
    }

    /** The address a run of {@code name} on this machine wrote, if its file exists and names a live process. */
    public static Optional<String> read(String name) {
        Path file = fileOf(name);
        try {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            if (lines.isEmpty() || lines.get(0).isBlank()) {
                return Optional.empty();
            }
            if (lines.size() > 1 && !lines.get(1).isBlank()) {
                long pid = Long.parseLong(lines.get(1).strip());
                if (ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false) == Boolean.FALSE) {
                    LOG.info("{} names process {}, which is no longer running", file, pid);
                    return Optional.empty();
                }
            }
            return Optional.of(lines.get(0).strip());
        } catch (java.nio.file.NoSuchFileException e) {
            return Optional.empty();
        } catch (IOException | NumberFormatException e) {
            LOG.warn("cannot read {}: {}", file, e.toString());
            return Optional.empty();
        }
    }

    /** Removes the file of {@code name} when it still holds {@code address} (a later run of the same name keeps its own). */
    public static void remove(String name, String address) {
        Path file = fileOf(name);
        try {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            if (!lines.isEmpty() && lines.get(0).strip().equals(address)) {
                Files.deleteIfExists(file);
            }
        } catch (java.nio.file.NoSuchFileException e) {
            // already gone
        } catch (IOException e) {
            LOG.warn("cannot remove {}: {}", file, e.toString());
        }
    }
}
