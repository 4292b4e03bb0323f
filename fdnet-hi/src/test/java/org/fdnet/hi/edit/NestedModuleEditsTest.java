package org.fdnet.hi.edit;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The editor's module edits on networks/nested-arm.fdn: nested modules add, delete, rename and undo as a tree. */
class NestedModuleEditsTest {
    private static final Path NESTED = Path.of("..", "networks", "nested-arm.fdn");

    private NetworkInfo original;
    private UndoableNetworkEditor editor;

    @BeforeEach
    void open() throws Exception {
        original = NetworkRepository.load(NESTED);
        NetworkLayout layout = LayoutRepository.load(LayoutRepository.sideFileOf(NESTED));
        editor = new UndoableNetworkEditor(NetworkRepository.load(NESTED), layout);
    }

    @Test
    void shouldDeleteAModuleWithItsNestedModulesAndUndoItExactly() {
        assertThat(editor.deleteModule("Arm").accepted()).isTrue();
        assertThat(editor.network().modules()).extracting(ModuleInfo::name).containsExactly("main");
        assertThat(editor.undo().accepted()).isTrue();
        assertThat(editor.network()).isEqualTo(original);
        assertThat(NetworkRepository.toText(editor.network())).isEqualTo(NetworkRepository.toText(original));
    }

    @Test
    void shouldRenameANestedModuleInPlaceWithItsChildrenAndTheirLayout() {
        assertThat(editor.renameModule("Arm/Hand", "Paw").accepted()).isTrue();
        assertThat(editor.network().modules()).extracting(ModuleInfo::name)
                .containsExactly("main", "Arm", "Arm/Paw", "Arm/Paw/Fingers", "Arm/Wrist");
        assertThat(editor.layout().module("Arm/Paw/Fingers").colour()).isEqualTo("#8E44AD");
        assertThat(editor.undo().accepted()).isTrue();
        assertThat(editor.network()).isEqualTo(original);
    }

    @Test
    void shouldAddAModuleInsideAnotherAndSaveItNested() throws Exception {
        assertThat(editor.addModule("Arm/Hand/Thumb", true).accepted()).isTrue();
        String saved = NetworkRepository.toText(editor.network());
        assertThat(saved).contains("<module name=\"Thumb\" loadatstart=\"yes\"/>");
        assertThat(NetworkRepository.fromText(saved, "saved").module("Arm/Hand/Thumb")).isNotNull();
        assertThat(editor.addModule("Leg/Foot", true).reason()).contains("inside module 'Leg'");
    }
}
