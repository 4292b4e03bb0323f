package org.fdnet.netinfo.xml;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.lifecycle.AfterProperty;
import net.jqwik.api.lifecycle.BeforeProperty;
import org.fdnet.bench.NetworkGenerator;
import org.fdnet.netinfo.NetworkInfo;

/** Saving and loading are inverse on every valid network, including names and values XML must escape. */
class RoundTripProperties {
    private Path dir;

    @BeforeProperty
    void createDirectory() throws IOException {
        dir = Files.createTempDirectory("fdnet-roundtrip");
    }

    @AfterProperty
    void deleteDirectory() throws IOException {
        try (var files = Files.list(dir)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Files.delete(f);
            }
        }
        Files.delete(dir);
    }

    private static NetworkInfo generated(long seed, int modules, int nodes) {
        return new NetworkGenerator(seed, true).generate(modules, nodes, nodes * 2);
    }

    @Property(tries = 150)
    void saveThenLoadGivesAnEqualNetwork(@ForAll long seed, @ForAll @IntRange(min = 1, max = 5) int modules,
                                         @ForAll @IntRange(min = 0, max = 40) int nodes) throws Exception {
        NetworkInfo network = generated(seed, modules, nodes);
        Path file = dir.resolve("n.fdn");
        NetworkRepository.save(network, file);
        assertThat(NetworkRepository.load(file)).isEqualTo(network);
    }

    @Property(tries = 100)
    void loadSaveLoadIsTheIdentityAndTheCanonicalFormIsStable(@ForAll long seed,
                                                               @ForAll @IntRange(min = 1, max = 4) int modules,
                                                               @ForAll @IntRange(min = 2, max = 30) int nodes) throws Exception {
        Path first = dir.resolve("first.fdn");
        NetworkRepository.save(generated(seed, modules, nodes), first);
        NetworkInfo loaded = NetworkRepository.load(first);
        Path second = dir.resolve("second.fdn");
        NetworkRepository.save(loaded, second);
        NetworkInfo reloaded = NetworkRepository.load(second);
        assertThat(reloaded).isEqualTo(loaded);
        assertThat(Files.readAllBytes(second)).isEqualTo(Files.readAllBytes(first));
    }

    @Property(tries = 50)
    void copiesAreEqualAndIndependent(@ForAll long seed) {
        NetworkInfo network = generated(seed, 3, 20);
        NetworkInfo copy = network.copy();
        assertThat(copy).isEqualTo(network);
        copy.addModule("OnlyInTheCopy", false);
        assertThat(network.module("OnlyInTheCopy")).isNull();
    }
}
