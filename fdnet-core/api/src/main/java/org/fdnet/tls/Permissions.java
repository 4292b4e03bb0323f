package org.fdnet.tls;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * Who may do what in a network: the grants of its permissions file ({@link PermissionsFile}), one per line:
 *
 * <pre>
 *   # NAME     RIGHT     PATTERN…
 *   *          read      *
 *   viewer     read      main Walk/Speed
 *   operator   write     Walk/* main/Certainty
 *   operator   unload    Walk
 *   logger     record
 * </pre>
 *
 * NAME is a certificate's name ({@code fdnet keys NAME}, its CN) or {@code *} for every member. A right is allowed when
 * a grant for the name or for {@code *} has a pattern that matches; nothing is allowed that no line grants. Patterns:
 * {@code *} matches any run of characters; for {@code read} and {@code write} a pattern is {@code Module/Node}, and a
 * module alone ({@code Walk}) means all its nodes; for {@code load}, {@code unload} and {@code reshape} it is a module
 * name; {@code record} takes none. Immutable and safe to share between threads.
 */
public final class Permissions {
    /** The grant of {@code fdnet keys}'s default file: every member may do everything, as without the file. */
    public static final String ALLOW_ALL_TEXT = """
            # Who may do what in this FDNet network. One grant per line: NAME RIGHT [PATTERN...]
            #   NAME     a certificate's name (fdnet keys NAME), or * for every member of the network
            #   RIGHT    read, write  (PATTERN: Module/Node or Module, * matches anything)
            #            load, unload, reshape  (PATTERN: a module, * matches anything)
            #            record  (the logger takes this member's events; no PATTERN)
            # Nothing is allowed that no line grants. After editing, sign the file again:
            #   fdnet keys --out DIR --sign-permissions
            # This default lets every member do everything.
            *  read     *
            *  write    *
            *  load     *
            *  unload   *
            *  reshape  *
            *  record
            """;
    private static final Pattern NAME = Pattern.compile("\\*|[A-Za-z0-9][A-Za-z0-9._-]*");
    private static final String EVERY_MEMBER = "*";

    private final Map<String, Map<Right, List<Pattern>>> grants;
    private final String source;

    private Permissions(Map<String, Map<Right, List<Pattern>>> grants, String source) {
        this.grants = grants;
        this.source = source;
    }

    /**
     * Every member may do everything: a process without TLS, where no certificate names the caller.
     *
     * @return grants that allow all
     */
    public static Permissions allowAll() {
        return parse(ALLOW_ALL_TEXT, "the default permissions");
    }

    /**
     * Reads grants.
     *
     * @param text   the file's text
     * @param source the file, named in messages
     * @return the grants
     * @throws IllegalArgumentException {@code SOURCE:LINE: what is wrong}
     */
    public static Permissions parse(String text, String source) {
        Map<String, Map<Right, List<Pattern>>> grants = new java.util.HashMap<>();
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String where = source + ":" + (i + 1) + ": ";
            String[] words = line.split("\\s+");
            if (words.length < 2) {
                throw new IllegalArgumentException(where + "a grant is NAME RIGHT [PATTERN...], was '" + line + "'");
            }
            if (!NAME.matcher(words[0]).matches()) {
                throw new IllegalArgumentException(where + "'" + words[0] + "' is not a certificate name nor *");
            }
            Right right = right(words[1], where);
            List<Pattern> patterns = new ArrayList<>();
            for (int w = 2; w < words.length; w++) {
                patterns.add(pattern(words[w], right, where));
            }
            if (right.scope() == Right.Scope.NONE) {
                if (!patterns.isEmpty()) {
                    throw new IllegalArgumentException(where + "'" + right.word() + "' takes no pattern");
                }
                patterns.add(Pattern.compile(".*"));
            } else if (patterns.isEmpty()) {
                throw new IllegalArgumentException(where + "'" + right.word() + "' needs at least one pattern"
                        + (right.scope() == Right.Scope.NODES ? " (Module/Node, Module or *)" : " (a module or *)"));
            }
            grants.computeIfAbsent(words[0], n -> new EnumMap<>(Right.class))
                    .computeIfAbsent(right, r -> new ArrayList<>()).addAll(patterns);
        }
        return new Permissions(grants, source);
    }

    /**
     * Whether {@code member} may use {@code right} on a node.
     *
     * @param member the caller's certificate name
     * @param right  a right whose scope is nodes ({@link Right#READ}, {@link Right#WRITE})
     * @param module the node's module
     * @param node   the node's name
     * @return null when allowed, else the refusal: the certificate, the node and the right it lacks
     */
    public String refusal(String member, Right right, String module, String node) {
        String subject = module + "/" + node;
        return allows(member, right, subject) ? null : refusalText(member, right, subject);
    }

    /**
     * Whether {@code member} may use {@code right} on a module (or, for {@link Right#RECORD}, at all).
     *
     * @param member the caller's certificate name
     * @param right  a right whose scope is modules, or {@link Right#RECORD} ({@code module} is then ignored)
     * @param module the module
     * @return null when allowed, else the refusal: the certificate, the module and the right it lacks
     */
    public String refusal(String member, Right right, String module) {
        String subject = right.scope() == Right.Scope.NONE ? "" : module;
        if (allows(member, right, subject)) {
            return null;
        }
        return right.scope() == Right.Scope.NONE
                ? "certificate '" + member + "' may not " + right.word() + " (no '" + right.word() + "' grant for it in "
                + source + ")"
                : refusalText(member, right, "module " + module);
    }

    private String refusalText(String member, Right right, String subject) {
        return "certificate '" + member + "' may not " + right.word() + " " + subject + " (no '" + right.word()
                + "' grant for it in " + source + ")";
    }

    private boolean allows(String member, Right right, String subject) {
        return matches(grants.get(member), right, subject) || matches(grants.get(EVERY_MEMBER), right, subject);
    }

    private static boolean matches(Map<Right, List<Pattern>> rights, Right right, String subject) {
        if (rights == null) {
            return false;
        }
        List<Pattern> patterns = rights.get(right);
        if (patterns == null) {
            return false;
        }
        for (Pattern p : patterns) {
            if (p.matcher(subject).matches()) {
                return true;
            }
        }
        return false;
    }

    private static Right right(String word, String where) {
        for (Right r : Right.values()) {
            if (r.word().equals(word.toLowerCase(Locale.ROOT))) {
                return r;
            }
        }
        List<String> words = new ArrayList<>();
        for (Right r : Right.values()) {
            words.add(r.word());
        }
        throw new IllegalArgumentException(where + "unknown right '" + word + "'; rights are " + String.join(", ", words));
    }

    private static Pattern pattern(String text, Right right, String where) {
        String glob = text;
        if (right.scope() == Right.Scope.NODES) {
            int slash = text.indexOf('/');
            if (slash < 0) {
                glob = text.equals("*") ? "*" : text + "/*";
            } else if (slash == 0 || slash == text.length() - 1 || text.indexOf('/', slash + 1) >= 0) {
                throw new IllegalArgumentException(where + "'" + text + "' is not Module/Node, Module or *");
            }
        } else if (text.indexOf('/') >= 0) {
            throw new IllegalArgumentException(where + "'" + right.word() + "' names modules, not nodes: '" + text + "'");
        }
        return Pattern.compile(globRegex(glob));
    }

    private static String globRegex(String glob) {
        String[] parts = glob.split("\\*", -1);
        StringBuilder regex = new StringBuilder(Pattern.quote(parts[0]));
        for (int i = 1; i < parts.length; i++) {
            regex.append(".*").append(Pattern.quote(parts[i]));
        }
        return regex.toString();
    }
}
