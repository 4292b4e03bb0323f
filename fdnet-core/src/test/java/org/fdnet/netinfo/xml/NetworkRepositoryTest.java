package org.fdnet.netinfo.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.netinfo.xml.NetworkFiles.data;
import static org.fdnet.netinfo.xml.NetworkFiles.read;
import static org.fdnet.netinfo.xml.NetworkFiles.relation;
import static org.fdnet.netinfo.xml.NetworkFiles.utf8;
import static org.fdnet.netinfo.xml.NetworkFiles.write;

import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class NetworkRepositoryTest {
    @TempDir
    Path dir;

    private static final String TWO_NODES = data("D") + relation("R");

    private Problem onlyProblem(Path file) {
        List<Problem> problems = problems(file);
        assertThat(problems).hasSize(1);
        return problems.get(0);
    }

    private static List<Problem> problems(Path file) {
        try {
            NetworkRepository.load(file);
        } catch (NetworkFileException e) {
            assertThat(e.problems()).isNotEmpty();
            return e.problems();
        }
        throw new AssertionError(file + " was accepted");
    }

    private static void assertAt(Problem problem, int line, String... messageParts) {
        assertThat(problem.line()).as("line of %s", problem).isEqualTo(line);
        assertThat(problem.column()).as("column of %s", problem).isPositive();
        for (String part : messageParts) {
            assertThat(problem.message()).contains(part);
        }
        assertThat(problem.toString()).matches(".+\\.fdn:" + line + ":\\d+: .+");
    }

    @Test
    void shouldLoadTheArmsExampleWithModulesAndCrossModuleReferences() throws Exception {
        NetworkInfo arms = NetworkRepository.load(Path.of("../networks/arms.fdn"));
        assertThat(arms.name()).isEqualTo("arms");
        assertThat(arms.modules()).extracting(m -> m.name() + ":" + m.loadAtStart())
                .containsExactly("main:true", "LeftArm:true", "RightArm:false");
        assertThat(arms.module("RightArm").connections())
                .contains(ConnectionInfo.reader(new NodeRef("LeftArm", "Shoulder"), new NodeRef("RightArm", "Mirror")));
        assertThat(arms.node(new NodeRef("LeftArm", "Servo")).parameters())
                .containsExactly(new Parameter("maxRate", ParameterType.DOUBLE, "2.0"));
    }

    @Test
    void shouldValidateAFileWithoutDoctypeAgainstTheBundledDtd() throws Exception {
        Path valid = NetworkFiles.file(dir, "plain.fdn", "<cnet>" + TWO_NODES + "<connection>" + read("D", "R") + "</connection></cnet>",
                StandardCharsets.UTF_8);
        assertThat(NetworkRepository.load(valid).totalCounts().readers()).isEqualTo(1);
        Path invalid = NetworkFiles.file(dir, "bad.fdn", "<cnet>\n<dstructure><name>D</name></dstructure></cnet>", StandardCharsets.UTF_8);
        assertAt(onlyProblem(invalid), 2, "dstructure");
        Path oneLine = NetworkFiles.file(dir, "line.fdn", "<?xml version=\"1.0\"?><cnet><bogus/></cnet>", StandardCharsets.UTF_8);
        Problem bogus = problems(oneLine).get(0);
        assertThat(bogus.message()).contains("bogus");
        assertThat(bogus.column()).as("column as the file has it, not as the parser saw it").isEqualTo(36);
        assertThat(NetworkRepository.read(valid).doctypeSystemId()).isNull();
    }

    @Test
    void shouldUseTheBundledDtdWhateverTheDoctypeNames() throws Exception {
        Path file = NetworkFiles.file(dir, "remote.fdn", "<?xml version=\"1.0\"?>\n<!DOCTYPE cnet SYSTEM \"http://127.0.0.1:9/evil.dtd\">\n<cnet>"
                + TWO_NODES + "</cnet>", StandardCharsets.UTF_8);
        assertThat(NetworkRepository.read(file).doctypeSystemId()).isEqualTo("http://127.0.0.1:9/evil.dtd");
        Path weaker = NetworkFiles.file(dir, "weaker.fdn", "<?xml version=\"1.0\"?>\n<!DOCTYPE cnet SYSTEM \"/dev/null\">\n<cnet>\n<bogus/></cnet>",
                StandardCharsets.UTF_8);
        assertAt(problems(weaker).get(0), 4, "bogus");
    }

    @Test
    void shouldReportAnUndeclaredElement() {
        assertAt(problems(utf8(dir, "<cnet>\n<robot/>\n</cnet>")).get(0), 4, "robot");
    }

    @Test
    void shouldReportAMissingRequiredChild() {
        Path file = utf8(dir, "<cnet>\n<pstructure><name>R</name><host>h</host><path></path></pstructure>\n</cnet>");
        assertAt(problems(file).get(0), 4, "pstructure");
    }

    @Test
    void shouldReportChildrenInTheWrongOrder() {
        Path file = utf8(dir, "<cnet>\n<dstructure><host>h</host><name>D</name><path></path><class>C</class></dstructure>\n</cnet>");
        assertAt(problems(file).get(0), 4, "dstructure");
    }

    @Test
    void shouldReportAnInvalidEnumeratedAttributeValue() {
        assertAt(onlyProblem(utf8(dir, "<cnet>\n<module name=\"Arm\" loadatstart=\"maybe\"/>\n</cnet>")), 4, "loadatstart", "maybe");
    }

    @Test
    void shouldReportAnUndeclaredAttribute() {
        assertAt(onlyProblem(utf8(dir, "<cnet>\n<module name=\"Arm\" colour=\"red\"/>\n</cnet>")), 4, "colour");
    }

    @Test
    void shouldReportAMissingRequiredAttribute() {
        assertAt(onlyProblem(utf8(dir, "<cnet>\n<module/>\n</cnet>")), 4, "name");
    }

    @Test
    void shouldReportTextWhereOnlyElementsMayStand() {
        assertAt(onlyProblem(utf8(dir, "<cnet>\n<connection>stray text</connection>\n</cnet>")), 4, "connection");
    }

    @Test
    void shouldReportContentInAnEmptyElementAndABadExistValue() {
        String body = "<cnet>" + TWO_NODES + "<connection>\n<read><data>D</data><proc>R</proc><exist value=\"maybe\"/></read>\n</connection></cnet>";
        assertAt(onlyProblem(utf8(dir, body)), 6, "maybe");
    }

    @Test
    void shouldReportEveryDtdViolationNotJustTheFirst() {
        List<Problem> problems = problems(utf8(dir, "<cnet>\n<robot/>\n<module name=\"A\" loadatstart=\"maybe\"/>\n</cnet>"));
        assertThat(problems).extracting(Problem::line).contains(4, 5);
        assertThat(problems).extracting(Problem::message).anyMatch(m -> m.contains("robot")).anyMatch(m -> m.contains("maybe"));
    }

    @Test
    void shouldReportAWrongRootElement() {
        assertThat(problems(utf8(dir, "<network/>"))).isNotEmpty();
    }

    @Test
    void shouldReportMalformedXmlWithItsPosition() {
        assertAt(onlyProblem(utf8(dir, "<cnet>\n<module name=\"A\">\n</cnet>")), 5, "module");
    }

    @Test
    void shouldReportADanglingReferenceAtItsLine() {
        String body = "<cnet>" + TWO_NODES + "<connection>\n" + read("Ghost", "R") + "</connection></cnet>";
        assertAt(onlyProblem(utf8(dir, body)), 6, "'Ghost'", "module 'main' has no node named 'Ghost'");
    }

    @Test
    void shouldReportAQualifiedReferenceToAMissingModuleOrNode() {
        String body = "<cnet>" + TWO_NODES + "<connection>\n" + read("Arm/D", "R") + read("main/Nope", "R") + "</connection></cnet>";
        List<Problem> problems = problems(utf8(dir, body));
        assertThat(problems).extracting(Problem::message).anyMatch(m -> m.contains("there is no module 'Arm'"))
                .anyMatch(m -> m.contains("module 'main' has no node named 'Nope'"));
    }

    @Test
    void shouldReportDuplicateNodeNamesInOneModule() {
        String body = "<cnet>\n" + data("D") + relation("D") + "</cnet>";
        assertAt(onlyProblem(utf8(dir, body)), 5, "already has a node named 'D'");
    }

    @Test
    void shouldAcceptTheSameNodeNameInTwoModules() throws Exception {
        String body = "<cnet>" + data("D") + "<module name=\"Arm\">" + data("D") + relation("R")
                + "<connection>" + read("D", "R") + read("main/D", "R") + "</connection></module></cnet>";
        NetworkInfo network = NetworkRepository.load(utf8(dir, body));
        assertThat(network.module("Arm").connections()).extracting(ConnectionInfo::data)
                .containsExactly(new NodeRef("Arm", "D"), new NodeRef("main", "D"));
    }

    @Test
    void shouldReportDuplicateModuleNamesAndTheReservedMain() {
        String body = "<cnet>\n<module name=\"A\"/>\n<module name=\"A\"/>\n<module name=\"main\"/>\n</cnet>";
        List<Problem> problems = problems(utf8(dir, body));
        assertThat(problems).extracting(Problem::line).containsExactly(5, 6);
        assertThat(problems.get(0).message()).contains("already has a module named 'A'");
        assertThat(problems.get(1).message()).contains("reserved");
    }

    @Test
    void shouldReportAConnectionThatDoesNotJoinOneDataAndOneRelation() {
        String body = "<cnet>" + TWO_NODES + data("E") + "<connection>\n" + write("D", "E") + "</connection></cnet>";
        assertAt(onlyProblem(utf8(dir, body)), 7, "must join one Data and one Relation", "main/E is a Data");
    }

    @Test
    void shouldReportADuplicateConnection() {
        String body = "<cnet>" + TWO_NODES + "<connection>\n" + read("D", "R") + read("main/D", "R") + "</connection></cnet>";
        assertAt(onlyProblem(utf8(dir, body)), 7, "duplicate Reader");
    }

    @Test
    void shouldReportATypedParameterWithAWrongValue() {
        String body = "<cnet>\n<pstructure><name>R</name><host>h</host><path></path><class>C</class>\n"
                + "<param name=\"period\" type=\"long\">10ms</param></pstructure></cnet>";
        assertAt(onlyProblem(utf8(dir, body)), 5, "'period'", "not a whole number");
    }

    @Test
    void shouldReportANodeNameContainingASlash() {
        assertAt(onlyProblem(utf8(dir, "<cnet>\n" + data("a/b") + "</cnet>")), 4, "may not contain '/'");
    }

    @Test
    void shouldRefuseAnExternalEntityWithoutReadingIt() throws Exception {
        Path secret = NetworkFiles.file(dir, "secret.txt", "TOP-SECRET", StandardCharsets.UTF_8);
        String text = "<?xml version=\"1.0\"?>\n<!DOCTYPE cnet [\n<!ENTITY leak SYSTEM \"" + secret.toUri() + "\">\n]>\n"
                + "<cnet name=\"&leak;\"/>";
        Problem problem = onlyProblem(NetworkFiles.file(dir, "xxe.fdn", text, StandardCharsets.UTF_8));
        assertThat(problem.line()).isEqualTo(3);
        assertThat(problem.message()).contains("'leak'", "refused").doesNotContain("TOP-SECRET");
    }

    @Test
    void shouldRefuseAnExternalParameterEntity() {
        String text = "<?xml version=\"1.0\"?>\n<!DOCTYPE cnet [\n<!ENTITY % remote SYSTEM \"http://127.0.0.1:9/x.dtd\">\n%remote;\n]>\n<cnet/>";
        Problem problem = onlyProblem(NetworkFiles.file(dir, "pe.fdn", text, StandardCharsets.UTF_8));
        assertThat(problem.line()).isEqualTo(3);
        assertThat(problem.message()).contains("refused");
    }

    @Test
    void shouldRefuseBillionLaughsFastWithoutExpandingIt() {
        StringBuilder text = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE cnet [\n<!ENTITY lol0 \"lol\">\n");
        for (int i = 1; i < 30; i++) {
            text.append("<!ENTITY lol").append(i).append(" \"").append(("&lol" + (i - 1) + ";").repeat(10)).append("\">\n");
        }
        text.append("]>\n<cnet name=\"&lol29;\"/>");
        Path bomb = NetworkFiles.file(dir, "bomb.fdn", text.toString(), StandardCharsets.UTF_8);
        long start = System.nanoTime();
        Problem problem = onlyProblem(bomb);
        long millis = (System.nanoTime() - start) / 1_000_000;
        assertThat(problem.line()).isEqualTo(3);
        assertThat(problem.message()).contains("entity declaration 'lol0' refused");
        assertThat(millis).as("refused before any expansion").isLessThan(5_000);
    }

    @Test
    void shouldReportBytesThatAreNotValidInTheDeclaredEncoding() {
        byte[] head = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<cnet name=\"".getBytes(StandardCharsets.US_ASCII);
        byte[] eucJp = "姿勢".getBytes(Charset.forName("EUC-JP"));
        byte[] tail = "\"/>".getBytes(StandardCharsets.US_ASCII);
        byte[] content = new byte[head.length + eucJp.length + tail.length];
        System.arraycopy(head, 0, content, 0, head.length);
        System.arraycopy(eucJp, 0, content, head.length, eucJp.length);
        System.arraycopy(tail, 0, content, head.length + eucJp.length, tail.length);
        Problem problem = problems(NetworkFiles.bytes(dir, "wrong.fdn", content)).get(0);
        assertThat(problem.line()).isEqualTo(2);
        assertThat(problem.message()).containsIgnoringCase("UTF-8");
    }

    @Test
    void shouldReportAnUnknownEncoding() {
        Path file = NetworkFiles.file(dir, "klingon.fdn", "<?xml version=\"1.0\" encoding=\"KLINGON-8\"?>\n<cnet/>", StandardCharsets.UTF_8);
        assertThat(problems(file).get(0).message()).contains("KLINGON-8");
    }

    @Test
    void shouldLoadEucJpAndShiftJisFilesWithJapaneseNames() throws Exception {
        for (String encoding : List.of("EUC-JP", "Shift_JIS")) {
            String text = "<?xml version=\"1.0\" encoding=\"" + encoding + "\"?>\n" + NetworkFiles.DOCTYPE
                    + "<cnet name=\"移動\">" + data("現在の姿勢") + relation("バランスを保つ")
                    + "<connection>" + read("現在の姿勢", "バランスを保つ") + "</connection>"
                    + "<module name=\"歩行\" loadatstart=\"yes\">" + relation("歩く") + "<connection>" + read("現在の姿勢", "歩く")
                    + "</connection></module></cnet>";
            Path file = NetworkFiles.file(dir, encoding + ".fdn", text, Charset.forName(encoding));
            NetworkInfo network = NetworkRepository.load(file);
            assertThat(network.name()).isEqualTo("移動");
            assertThat(network.module("歩行").connections())
                    .containsExactly(ConnectionInfo.reader(new NodeRef("main", "現在の姿勢"), new NodeRef("歩行", "歩く")));
            Path saved = dir.resolve(encoding + "-saved.fdn");
            NetworkRepository.save(network, saved);
            assertThat(Files.readString(saved, StandardCharsets.UTF_8)).startsWith("<?xml version=\"1.0\" encoding=\"UTF-8\"?>")
                    .contains("現在の姿勢");
            assertThat(NetworkRepository.load(saved)).isEqualTo(network);
        }
    }

    @Test
    void shouldReadInlineDeclarationsAndTheExistFlagAndWriteThemBack() throws Exception {
        String body = "<cnet name=\"inline\">" + relation("R") + "<connection>\n<read><name>tap</name>"
                + "<dstructure><name>Tap</name><host>h</host><path>p</path><class>C</class><param>1</param></dstructure>"
                + "<proc>R</proc><exist value=\"no\"/></read>\n</connection></cnet>";
        NetworkInfo network = NetworkRepository.load(utf8(dir, body));
        ConnectionInfo tap = network.main().connections().get(0);
        assertThat(tap).isEqualTo(new ConnectionInfo(ConnectionKind.READER, "tap", new NodeRef("main", "Tap"),
                new NodeRef("main", "R"), false, true, false));
        assertThat(network.node(tap.data()).kind()).isEqualTo(NodeKind.DATA);
        String saved = new String(NetworkRepository.toBytes(network, "cnet.dtd"), StandardCharsets.UTF_8);
        assertThat(saved).containsPattern("<dstructure>\\s*<name>Tap</name>").contains("<exist value=\"no\"/>");
        Path again = NetworkFiles.file(dir, "again.fdn", saved, StandardCharsets.UTF_8);
        assertThat(NetworkRepository.load(again)).isEqualTo(network);
        assertThat(NetworkRepository.toBytes(NetworkRepository.load(again), "cnet.dtd")).isEqualTo(saved.getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void shouldKeepTheFileOrderAndBytesOfACanonicalFile() throws Exception {
        Path arms = Path.of("../networks/arms.fdn");
        NetworkDocument document = NetworkRepository.read(arms);
        byte[] rewritten = NetworkRepository.toBytes(document.network(), document.doctypeSystemId(), document.leadingComments());
        assertThat(new String(rewritten, StandardCharsets.UTF_8)).isEqualTo(Files.readString(arms));
    }

    @Test
    void shouldReportAMissingFileByName() {
        Problem problem = onlyProblem(dir.resolve("absent.fdn"));
        assertThat(problem.toString()).endsWith("absent.fdn: no such file");
    }

    @Test
    void shouldRejectWriterNodesDeclaredInline() {
        assertThatThrownBy(() -> new ConnectionInfo(ConnectionKind.WRITER, null, new NodeRef("m", "d"), new NodeRef("m", "r"),
                true, true, false)).isInstanceOf(IllegalArgumentException.class);
    }
}
