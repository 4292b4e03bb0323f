package org.fdnet.tls;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class PermissionsTest {
    private static final Permissions GRANTS = Permissions.parse("""
            # a comment
            *         read     *
            operator  write    Walk main/Certainty
            operator  unload   Walk
            operator  reshape  W*
            logger    record
            """, "permissions");

    @Test
    void shouldAllowWhatALineGrantsToTheNameOrToEveryMember() {
        assertThat(GRANTS.refusal("viewer", Right.READ, "Gait", "Phase")).isNull();
        assertThat(GRANTS.refusal("operator", Right.WRITE, "Walk", "Speed")).isNull();
        assertThat(GRANTS.refusal("operator", Right.WRITE, "main", "Certainty")).isNull();
        assertThat(GRANTS.refusal("operator", Right.UNLOAD, "Walk")).isNull();
        assertThat(GRANTS.refusal("operator", Right.RESHAPE, "Wander")).isNull();
        assertThat(GRANTS.refusal("logger", Right.RECORD, "")).isNull();
    }

    @Test
    void shouldRefuseWhatNoLineGrantsNamingTheCertificateTheSubjectAndTheRight() {
        assertThat(GRANTS.refusal("viewer", Right.WRITE, "main", "Certainty"))
                .isEqualTo("certificate 'viewer' may not write main/Certainty (no 'write' grant for it in permissions)");
        assertThat(GRANTS.refusal("operator", Right.WRITE, "main", "Map")).contains("'operator'").contains("main/Map");
        assertThat(GRANTS.refusal("operator", Right.UNLOAD, "Gait"))
                .isEqualTo("certificate 'operator' may not unload module Gait (no 'unload' grant for it in permissions)");
        assertThat(GRANTS.refusal("operator", Right.LOAD, "Walk")).contains("may not load module Walk");
        assertThat(GRANTS.refusal("operator", Right.RECORD, "")).contains("'operator' may not record");
        assertThat(GRANTS.refusal("operator", Right.RESHAPE, "*")).as("servant messages need every module")
                .contains("reshape module *");
    }

    @Test
    void shouldAllowEverythingByDefault() {
        Permissions all = Permissions.allowAll();
        for (Right r : Right.values()) {
            assertThat(all.refusal("anyone", r, "Walk", "Speed")).isNull();
            assertThat(all.refusal("anyone", r, "*")).isNull();
        }
    }

    @Test
    void shouldRejectABadLineWithItsFileAndLineNumber() {
        assertThatThrownBy(() -> Permissions.parse("* read *\nviewer wirte main\n", "DIR/permissions"))
                .hasMessage("DIR/permissions:2: unknown right 'wirte'; rights are read, write, load, unload, reshape,"
                        + " record");
        assertThatThrownBy(() -> Permissions.parse("viewer unload Walk/Speed", "p"))
                .hasMessage("p:1: 'unload' names modules, not nodes: 'Walk/Speed'");
        assertThatThrownBy(() -> Permissions.parse("viewer write", "p")).hasMessageStartingWith("p:1: 'write' needs");
        assertThatThrownBy(() -> Permissions.parse("logger record main", "p")).hasMessage("p:1: 'record' takes no pattern");
        assertThatThrownBy(() -> Permissions.parse("a/b read *", "p")).hasMessageContaining("not a certificate name");
    }
}
