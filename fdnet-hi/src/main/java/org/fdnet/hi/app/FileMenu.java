package org.fdnet.hi.app;

import java.io.IOException;
import java.nio.file.Path;
import javax.swing.Action;
import javax.swing.JFileChooser;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** File: new, open, recent files, save, save as, export PNG/SVG, quit — each asking before edits are lost. */
final class FileMenu {
    private static final Logger LOG = LoggerFactory.getLogger(FileMenu.class);

    private final HiWindow window;
    private final JMenu menu = new JMenu("File");
    private final JMenu recentMenu = new JMenu("Open Recent");
    private final Action save;
    private final Action saveAs;
    private final Action exportPng;
    private final Action exportSvg;

    FileMenu(HiWindow window) {
        this.window = window;
        menu.setName("menu.file");
        menu.add(MenuItems.action("New", "control N", this::newNetwork));
        menu.add(MenuItems.action("Open…", "control O", this::open));
        menu.add(recentMenu);
        menu.addSeparator();
        save = MenuItems.action("Save", "control S", this::save);
        saveAs = MenuItems.action("Save As…", "control shift S", this::saveAs);
        menu.add(save);
        menu.add(saveAs);
        menu.addSeparator();
        exportPng = MenuItems.action("Export PNG…", null, () -> export("png"));
        exportSvg = MenuItems.action("Export SVG…", null, () -> export("svg"));
        menu.add(exportPng);
        menu.add(exportSvg);
        menu.addSeparator();
        menu.add(MenuItems.action("Quit", "control Q", this::quit));
    }

    JMenu menu() {
        return menu;
    }

    void refresh() {
        boolean open = window.current() != null;
        save.setEnabled(open);
        saveAs.setEnabled(open);
        exportPng.setEnabled(open);
        exportSvg.setEnabled(open);
        recentMenu.removeAll();
        for (Path p : window.recent().list()) {
            JMenuItem item = new JMenuItem(p.toString());
            item.addActionListener(e -> {
                if (window.mayDiscard()) {
                    window.open(p);
                }
            });
            recentMenu.add(item);
        }
        recentMenu.setEnabled(recentMenu.getItemCount() > 0);
    }

    private void newNetwork() {
        if (window.mayDiscard()) {
            window.show(OpenNetwork.empty());
            window.status().info("New network");
        }
    }

    private void open() {
        if (!window.mayDiscard()) {
            return;
        }
        JFileChooser chooser = chooser("FDNet networks (.fdn)", "fdn");
        if (chooser.showOpenDialog(window) == JFileChooser.APPROVE_OPTION) {
            window.open(chooser.getSelectedFile().toPath());
        }
    }

    /** Saves to the network's file (asking for one if it has none); false if not saved. */
    boolean save() {
        OpenNetwork current = window.current();
        if (current == null) {
            return false;
        }
        if (current.file() == null) {
            return saveAs();
        }
        return saveTo(current.file());
    }

    boolean saveAs() {
        JFileChooser chooser = chooser("FDNet networks (.fdn)", "fdn");
        if (chooser.showSaveDialog(window) != JFileChooser.APPROVE_OPTION) {
            return false;
        }
        Path target = chooser.getSelectedFile().toPath();
        if (!target.getFileName().toString().endsWith(".fdn")) {
            target = target.resolveSibling(target.getFileName() + ".fdn");
        }
        return saveTo(target);
    }

    boolean saveTo(Path target) {
        try {
            window.current().saveAs(target);
            window.recent().add(target);
            window.refreshTitle();
            refresh();
            window.status().info("Saved " + target + " and its layout");
            return true;
        } catch (IOException e) {
            LOG.warn("saving {} failed", target, e);
            window.status().error("Could not save " + target + ": " + e.getMessage());
            return false;
        }
    }

    private void export(String format) {
        JFileChooser chooser = chooser(format.toUpperCase() + " image", format);
        if (chooser.showSaveDialog(window) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path target = chooser.getSelectedFile().toPath();
        if (!target.getFileName().toString().endsWith("." + format)) {
            target = target.resolveSibling(target.getFileName() + "." + format);
        }
        try {
            if (format.equals("png")) {
                GraphExport.png(window.current().scene(), target);
            } else {
                GraphExport.svg(window.current().scene(), target);
            }
            window.status().info("Exported the graph to " + target);
        } catch (IOException e) {
            LOG.warn("export to {} failed", target, e);
            window.status().error("Could not export to " + target + ": " + e.getMessage());
        }
    }

    void quit() {
        if (window.mayDiscard()) {
            window.dispose();
        }
    }

    private JFileChooser chooser(String description, String extension) {
        JFileChooser chooser = new JFileChooser();
        OpenNetwork current = window.current();
        if (current != null && current.file() != null) {
            chooser.setCurrentDirectory(current.file().toAbsolutePath().getParent().toFile());
        }
        chooser.setFileFilter(new FileNameExtensionFilter(description, extension));
        return chooser;
    }
}
