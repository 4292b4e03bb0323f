package org.fdnet.runtime.library;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * A small, safe arithmetic language for {@link Expression} (no script engine, no reflection: only the
 * operators and functions listed here). Every value is a vector of doubles; a number is a vector of one,
 * and operators apply element by element, a number spreading over a vector.
 *
 * <pre>
 *   expr    := or ('?' expr ':' expr)?
 *   or      := and ('||' and)*          and := cmp ('&amp;&amp;' cmp)*
 *   cmp     := sum (('&lt;'|'&gt;'|'&lt;='|'&gt;='|'=='|'!=') sum)?
 *   sum     := product (('+'|'-') product)*
 *   product := unary (('*'|'/'|'%') unary)*
 *   unary   := ('-'|'+'|'!') unary | power        power := postfix ('^' unary)?
 *   postfix := primary ('[' expr ']')*
 *   primary := number | name | name '(' expr (',' expr)* ')' | '(' expr ')' | '[' expr (',' expr)* ']'
 * </pre>
 *
 * Names: {@code in0, in1, ...} (inputs by position), an input's node name when it is a valid name,
 * {@code t} (seconds since start), {@code pi}, {@code e}. Functions: see {@link ExpressionFunctions}.
 */
final class ExpressionParser {
    /** A compiled expression. */
    interface Node {
        double[] eval(Env env);
    }

    /** Where names get their values. */
    interface Env {
        double[] variable(String name);
    }

    /**
     * How deep brackets, conditionals and prefix operators may nest: the parser and the compiled expression
     * recurse once per level, so an unbounded depth would overflow the stack instead of naming the column.
     */
    static final int MAX_DEPTH = 200;

    private final String text;
    private int pos;
    private int depth;

    private ExpressionParser(String text) {
        this.text = text;
    }

    /** Compiles {@code text}, or throws IllegalArgumentException naming the column and what was expected. */
    static Node parse(String text) {
        ExpressionParser p = new ExpressionParser(text);
        Node n = p.expr();
        p.skipSpace();
        if (p.pos < text.length()) {
            throw p.error("unexpected '" + text.charAt(p.pos) + "'");
        }
        return n;
    }

    /** Every name the expression reads (for checks at init). */
    static List<String> names(String text) {
        List<String> names = new ArrayList<>();
        ExpressionParser p = new ExpressionParser(text);
        while (p.pos < text.length()) {
            char c = text.charAt(p.pos);
            if (Character.isLetter(c) || c == '_') {
                int start = p.pos;
                while (p.pos < text.length() && (Character.isLetterOrDigit(text.charAt(p.pos)) || text.charAt(p.pos) == '_')) {
                    p.pos++;
                }
                p.skipSpace();
                if (p.pos >= text.length() || text.charAt(p.pos) != '(') {
                    names.add(text.substring(start, p.pos).strip());
                }
            } else if (Character.isDigit(c) || c == '.') {
                while (p.pos < text.length() && (Character.isLetterOrDigit(text.charAt(p.pos)) || text.charAt(p.pos) == '.')) {
                    p.pos++;
                }
            } else {
                p.pos++;
            }
        }
        return names;
    }

    private Node expr() {
        return nested(this::conditional);
    }

    /** One level deeper: refused past {@link #MAX_DEPTH}. */
    private Node nested(Supplier<Node> level) {
        if (++depth > MAX_DEPTH) {
            throw error("nested deeper than " + MAX_DEPTH + " levels");
        }
        try {
            return level.get();
        } finally {
            depth--;
        }
    }

    private Node conditional() {
        Node cond = or();
        if (eat("?")) {
            Node yes = expr();
            expect(":");
            Node no = expr();
            return env -> {
                double[] c = cond.eval(env);
                double[] a = yes.eval(env);
                double[] b = no.eval(env);
                return Vectors.select(c, a, b);
            };
        }
        return cond;
    }

    private Node or() {
        Node left = and();
        while (eat("||")) {
            Node l = left;
            Node r = and();
            left = env -> Vectors.combine(l.eval(env), r.eval(env), (a, b) -> a != 0 || b != 0 ? 1 : 0);
        }
        return left;
    }

    private Node and() {
        Node left = comparison();
        while (eat("&&")) {
            Node l = left;
            Node r = comparison();
            left = env -> Vectors.combine(l.eval(env), r.eval(env), (a, b) -> a != 0 && b != 0 ? 1 : 0);
        }
        return left;
    }

    private Node comparison() {
        Node left = sum();
        for (String op : new String[] {"<=", ">=", "==", "!=", "<", ">"}) {
            if (eat(op)) {
                Node l = left;
                Node r = sum();
                Vectors.Op f = switch (op) {
                    case "<=" -> (a, b) -> a <= b ? 1 : 0;
                    case ">=" -> (a, b) -> a >= b ? 1 : 0;
                    case "==" -> (a, b) -> a == b ? 1 : 0;
                    case "!=" -> (a, b) -> a != b ? 1 : 0;
                    case "<" -> (a, b) -> a < b ? 1 : 0;
                    default -> (a, b) -> a > b ? 1 : 0;
                };
                return env -> Vectors.combine(l.eval(env), r.eval(env), f);
            }
        }
        return left;
    }

    private Node sum() {
        Node left = product();
        while (true) {
            if (eat("+")) {
                Node l = left;
                Node r = product();
                left = env -> Vectors.combine(l.eval(env), r.eval(env), Double::sum);
            } else if (eat("-")) {
                Node l = left;
                Node r = product();
                left = env -> Vectors.combine(l.eval(env), r.eval(env), (a, b) -> a - b);
            } else {
                return left;
            }
        }
    }

    private Node product() {
        Node left = unary();
        while (true) {
            Vectors.Op op;
            if (eat("*")) {
                op = (a, b) -> a * b;
            } else if (eat("/")) {
                op = (a, b) -> a / b;
            } else if (eat("%")) {
                op = (a, b) -> a % b;
            } else {
                return left;
            }
            Node l = left;
            Node r = unary();
            Vectors.Op f = op;
            left = env -> Vectors.combine(l.eval(env), r.eval(env), f);
        }
    }

    private Node unary() {
        return nested(this::prefixed);
    }

    private Node prefixed() {
        if (eat("-")) {
            Node n = unary();
            return env -> Vectors.map(n.eval(env), a -> -a);
        }
        if (eat("+")) {
            return unary();
        }
        if (peek("!") && !peek("!=")) {
            eat("!");
            Node n = unary();
            return env -> Vectors.map(n.eval(env), a -> a == 0 ? 1 : 0);
        }
        return power();
    }

    private Node power() {
        Node base = postfix();
        if (eat("^")) {
            Node exponent = unary();
            return env -> Vectors.combine(base.eval(env), exponent.eval(env), Math::pow);
        }
        return base;
    }

    private Node postfix() {
        Node n = primary();
        while (eat("[")) {
            Node vector = n;
            Node index = expr();
            expect("]");
            int column = pos;
            n = env -> {
                double[] v = vector.eval(env);
                double[] i = index.eval(env);
                if (i.length != 1) {
                    throw new IllegalArgumentException("index " + Vectors.text(i) + " is not one number (column "
                            + column + ")");
                }
                int k = (int) Math.round(i[0]);
                if (k < 0 || k >= v.length) {
                    throw new IllegalArgumentException("index " + Vectors.text(i) + " is outside a vector of "
                            + v.length + " (column " + column + ")");
                }
                return new double[] {v[k]};
            };
        }
        return n;
    }

    private Node primary() {
        skipSpace();
        if (pos >= text.length()) {
            throw error("expected a value");
        }
        char c = text.charAt(pos);
        if (Character.isDigit(c) || c == '.') {
            return number();
        }
        if (eat("(")) {
            Node n = expr();
            expect(")");
            return n;
        }
        if (eat("[")) {
            List<Node> items = list("]");
            Node[] parts = items.toArray(Node[]::new);
            return env -> Vectors.concat(parts, env);
        }
        if (Character.isLetter(c) || c == '_') {
            String name = name();
            if (eat("(")) {
                List<Node> args = list(")");
                return ExpressionFunctions.call(name.toLowerCase(Locale.ROOT), args, this::error);
            }
            return switch (name) {
                case "pi" -> env -> new double[] {Math.PI};
                case "e" -> env -> new double[] {Math.E};
                default -> env -> env.variable(name);
            };
        }
        throw error("expected a value, found '" + c + "'");
    }

    private List<Node> list(String close) {
        List<Node> items = new ArrayList<>();
        if (eat(close)) {
            return items;
        }
        do {
            items.add(expr());
        } while (eat(","));
        expect(close);
        return items;
    }

    private Node number() {
        int start = pos;
        while (pos < text.length() && (Character.isDigit(text.charAt(pos)) || text.charAt(pos) == '.')) {
            pos++;
        }
        if (pos < text.length() && (text.charAt(pos) == 'e' || text.charAt(pos) == 'E')) {
            int save = pos;
            pos++;
            if (pos < text.length() && (text.charAt(pos) == '+' || text.charAt(pos) == '-')) {
                pos++;
            }
            if (pos < text.length() && Character.isDigit(text.charAt(pos))) {
                while (pos < text.length() && Character.isDigit(text.charAt(pos))) {
                    pos++;
                }
            } else {
                pos = save;
            }
        }
        String literal = text.substring(start, pos);
        try {
            double[] value = {Double.parseDouble(literal)};
            return env -> value;
        } catch (NumberFormatException e) {
            throw error("'" + literal + "' is not a number");
        }
    }

    private String name() {
        int start = pos;
        while (pos < text.length() && (Character.isLetterOrDigit(text.charAt(pos)) || text.charAt(pos) == '_')) {
            pos++;
        }
        return text.substring(start, pos);
    }

    private boolean peek(String token) {
        skipSpace();
        return text.startsWith(token, pos);
    }

    private boolean eat(String token) {
        if (peek(token)) {
            pos += token.length();
            return true;
        }
        return false;
    }

    private void expect(String token) {
        if (!eat(token)) {
            throw error("expected '" + token + "'");
        }
    }

    private void skipSpace() {
        while (pos < text.length() && Character.isWhitespace(text.charAt(pos))) {
            pos++;
        }
    }

    IllegalArgumentException error(String message) {
        return new IllegalArgumentException("expression '" + text + "', column " + (pos + 1) + ": " + message);
    }
}
