package org.fdnet.netinfo.xml;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.UnmarshalException;
import jakarta.xml.bind.Unmarshaller;
import jakarta.xml.bind.ValidationEvent;
import jakarta.xml.bind.ValidationEventLocator;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParserFactory;
import javax.xml.transform.sax.SAXSource;
import org.xml.sax.ContentHandler;
import org.xml.sax.DTDHandler;
import org.xml.sax.EntityResolver;
import org.xml.sax.ErrorHandler;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXNotRecognizedException;
import org.xml.sax.SAXNotSupportedException;
import org.xml.sax.SAXParseException;
import org.xml.sax.XMLReader;
import org.xml.sax.ext.DeclHandler;
import org.xml.sax.ext.EntityResolver2;
import org.xml.sax.ext.LexicalHandler;
import org.xml.sax.helpers.XMLFilterImpl;

/**
 * Reads one XML file into JAXB bindings, validating it against a {@link BundledDtd} and refusing
 * what could hurt the reader:
 * <ul>
 *   <li>the DTD is always the bundled one, whatever the DOCTYPE names, and is supplied when the file
 *       has no DOCTYPE at all;</li>
 *   <li>any entity declaration is refused at once, at its position: no external entity is ever
 *       resolved and no entity is ever expanded, so "billion laughs" costs nothing;</li>
 *   <li>the encoding the file declares is honoured (UTF-8, EUC-JP, Shift_JIS, ...); bytes that are
 *       not valid in it are an error with their position;</li>
 *   <li>validation errors are collected, not ignored: JAXB by default swallows them, so every parser
 *       error reaches {@link #problems()} with its line and column.</li>
 * </ul>
 * One instance reads one file.
 */
final class GuardedXmlReader {
    /** Files are read whole (a network of 10,000 nodes is about 3 MiB); this bounds the memory a file can take. */
    static final long MAX_FILE_BYTES = 64L * 1024 * 1024;

    private final Path file;
    private final byte[] content;
    private final BundledDtd dtd;
    private DoctypeSupplier doctype;
    private final List<Problem> problems = new ArrayList<>();
    private Locator locator;
    private String doctypeSystemId;
    private boolean rootStarted;
    private boolean inDtd;
    private final List<String> leadingComments = new ArrayList<>();
    private int innerComments;

    GuardedXmlReader(Path file, BundledDtd dtd) {
        this(file, null, dtd);
    }

    /** Reads {@code content} (a document that did not come from a file) and names {@code source} in problems. */
    GuardedXmlReader(Path source, byte[] content, BundledDtd dtd) {
        this.file = source;
        this.content = content;
        this.dtd = dtd;
    }

    /** The problems found so far, in file order. */
    List<Problem> problems() {
        List<Problem> sorted = new ArrayList<>(problems);
        Collections.sort(sorted);
        return sorted;
    }

    void add(int line, int column, String message) {
        int fileColumn = doctype == null ? column : doctype.correctColumn(line, column);
        problems.add(new Problem(file, line, fileColumn, message));
    }

    /** The comments before the root element, which a rewrite keeps. */
    List<String> leadingComments() {
        return leadingComments;
    }

    /** How many comments stood inside the root element (JAXB does not keep them). */
    int innerComments() {
        return innerComments;
    }

    /** The SYSTEM id of the file's DOCTYPE, or {@code null} when it had none. */
    String doctypeSystemId() {
        return doctype != null && doctype.inserted() ? null : doctypeSystemId;
    }

    /**
     * Unmarshals the file; returns {@code null} (with problems recorded) when it is not well-formed
     * or cannot be read. A non-null result may still come with validation problems.
     */
    <T> T read(JAXBContext context, Class<T> rootType) {
        try {
            long size = content != null ? content.length : Files.size(file);
            if (size > MAX_FILE_BYTES) {
                add(0, 0, "the file is " + size / (1024 * 1024) + " MiB; FDNet reads files of at most "
                        + MAX_FILE_BYTES / (1024 * 1024) + " MiB");
                return null;
            }
            doctype = DoctypeSupplier.prepare(content != null ? content : Files.readAllBytes(file), dtd);
            InputSource source = doctype.source();
            source.setSystemId(file.toUri().toString());
            Unmarshaller unmarshaller = context.createUnmarshaller();
            unmarshaller.setEventHandler(this::handle);
            Object result = unmarshaller.unmarshal(new SAXSource(newReader(), source));
            return rootType.isInstance(result) ? rootType.cast(result) : null;
        } catch (NoSuchFileException e) {
            add(0, 0, "no such file");
        } catch (IOException e) {
            add(0, 0, "cannot read the file: " + e.getMessage());
        } catch (UnmarshalException e) {
            recordAbort(e);
        } catch (JAXBException | SAXException | ParserConfigurationException e) {
            add(0, 0, "cannot set up the XML reader: " + e);
        }
        return null;
    }

    private boolean handle(ValidationEvent event) {
        boolean fatal = event.getSeverity() == ValidationEvent.FATAL_ERROR;
        // Validity is the parser's job (against the DTD); JAXB's own "unexpected element" echoes are duplicates.
        if (fatal || event.getLinkedException() instanceof SAXParseException) {
            ValidationEventLocator at = event.getLocator();
            record(at == null ? 0 : at.getLineNumber(), at == null ? 0 : at.getColumnNumber(), event.getMessage());
        }
        return !fatal;
    }

    private void recordAbort(UnmarshalException e) {
        Throwable cause = e.getLinkedException() != null ? e.getLinkedException() : e.getCause();
        if (cause instanceof SAXParseException spe) {
            record(spe.getLineNumber(), spe.getColumnNumber(), spe.getMessage());
        } else if (cause != null && problems.isEmpty()) {
            add(0, 0, String.valueOf(cause.getMessage()));
        } else if (problems.isEmpty()) {
            add(0, 0, String.valueOf(e.getMessage()));
        }
    }

    private void record(int line, int column, String message) {
        String clean = message == null ? "invalid XML" : message.strip();
        for (Problem p : problems) {
            if (p.line() == line && p.column() == column && p.message().equals(clean)) {
                return;
            }
        }
        add(line, column, clean);
    }

    private XMLReader newReader() throws ParserConfigurationException, SAXException {
        SAXParserFactory factory = SAXParserFactory.newInstance();
        factory.setNamespaceAware(true);
        factory.setValidating(true);
        factory.setXIncludeAware(false);
        factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        XMLReader parser = factory.newSAXParser().getXMLReader();
        parser.setFeature("http://xml.org/sax/features/use-entity-resolver2", true);
        parser.setProperty("http://xml.org/sax/properties/declaration-handler", new EntityRefusal());
        parser.setProperty("http://xml.org/sax/properties/lexical-handler", new DoctypeWatcher());
        return new PinnedReader(parser, new BundledDtdResolver());
    }

    private SAXParseException refusal(String message) {
        return new SAXParseException(message, locator);
    }

    /** Serves the bundled DTD for the external subset; refuses every other external resource. */
    private final class BundledDtdResolver implements EntityResolver2 {
        @Override
        public InputSource getExternalSubset(String name, String baseUri) {
            return dtd.inputSource();
        }

        @Override
        public InputSource resolveEntity(String name, String publicId, String baseUri, String systemId)
                throws SAXException {
            // SAX names the external DTD subset "[dtd]"; the JDK's parser passes null.
            if (name == null || "[dtd]".equals(name)) {
                return dtd.inputSource();
            }
            throw refusal("external entity '" + name + "' (" + systemId + ") refused: FDNet files may not load other files");
        }

        @Override
        public InputSource resolveEntity(String publicId, String systemId) throws SAXException {
            throw refusal("external resource (" + systemId + ") refused: FDNet files may not load other files");
        }
    }

    /** Refuses entity declarations where they stand: FDNet files never need entities. */
    private final class EntityRefusal implements DeclHandler {
        @Override
        public void internalEntityDecl(String name, String value) throws SAXException {
            throw refusal("entity declaration '" + name + "' refused: FDNet files may not declare entities");
        }

        @Override
        public void externalEntityDecl(String name, String publicId, String systemId) throws SAXException {
            throw refusal("external entity '" + name + "' (" + systemId + ") refused: FDNet files may not load other files");
        }

        @Override
        public void elementDecl(String name, String model) {
            // element declarations are the grammar itself
        }

        @Override
        public void attributeDecl(String eName, String aName, String type, String mode, String value) {
            // attribute declarations are the grammar itself
        }
    }

    /** Notes the DOCTYPE's SYSTEM id and the comments, so {@code fdnet fmt} can keep them. */
    private final class DoctypeWatcher implements LexicalHandler {
        @Override
        public void startDTD(String name, String publicId, String systemId) {
            doctypeSystemId = systemId;
            inDtd = true;
        }

        @Override
        public void endDTD() {
            inDtd = false;
        }

        @Override
        public void startEntity(String name) {
        }

        @Override
        public void endEntity(String name) {
        }

        @Override
        public void startCDATA() {
        }

        @Override
        public void endCDATA() {
        }

        @Override
        public void comment(char[] ch, int start, int length) {
            if (inDtd) {
                return;
            }
            if (rootStarted) {
                innerComments++;
            } else {
                leadingComments.add(new String(ch, start, length));
            }
        }
    }

    /**
     * The XMLReader JAXB sees: the parser itself, except that its entity resolver is pinned to ours
     * (nobody may swap in one that fetches what a DOCTYPE names) and the content handler JAXB installs
     * is wrapped to keep the parser's locator for our own error positions.
     */
    private final class PinnedReader implements XMLReader {
        private final XMLReader parser;

        PinnedReader(XMLReader parser, EntityResolver2 resolver) {
            this.parser = parser;
            parser.setEntityResolver(resolver);
        }

        @Override
        public boolean getFeature(String name) throws SAXNotRecognizedException, SAXNotSupportedException {
            return parser.getFeature(name);
        }

        @Override
        public void setFeature(String name, boolean value) throws SAXNotRecognizedException, SAXNotSupportedException {
            parser.setFeature(name, value);
        }

        @Override
        public Object getProperty(String name) throws SAXNotRecognizedException, SAXNotSupportedException {
            return parser.getProperty(name);
        }

        @Override
        public void setProperty(String name, Object value) throws SAXNotRecognizedException, SAXNotSupportedException {
            parser.setProperty(name, value);
        }

        @Override
        public void setEntityResolver(EntityResolver ignored) {
            // pinned: see the class comment
        }

        @Override
        public EntityResolver getEntityResolver() {
            return parser.getEntityResolver();
        }

        @Override
        public void setDTDHandler(DTDHandler handler) {
            parser.setDTDHandler(handler);
        }

        @Override
        public DTDHandler getDTDHandler() {
            return parser.getDTDHandler();
        }

        @Override
        public void setContentHandler(ContentHandler handler) {
            parser.setContentHandler(new LocatorKeeper(handler));
        }

        @Override
        public ContentHandler getContentHandler() {
            return parser.getContentHandler();
        }

        @Override
        public void setErrorHandler(ErrorHandler handler) {
            parser.setErrorHandler(handler);
        }

        @Override
        public ErrorHandler getErrorHandler() {
            return parser.getErrorHandler();
        }

        @Override
        public void parse(InputSource input) throws IOException, SAXException {
            parser.parse(input);
        }

        @Override
        public void parse(String systemId) throws IOException, SAXException {
            parser.parse(systemId);
        }
    }

    /** Forwards every content event to JAXB, noting the locator on the way. */
    private final class LocatorKeeper extends XMLFilterImpl {
        LocatorKeeper(ContentHandler target) {
            setContentHandler(target);
        }

        @Override
        public void setDocumentLocator(Locator l) {
            locator = l;
            super.setDocumentLocator(l);
        }

        @Override
        public void startElement(String uri, String localName, String qName, org.xml.sax.Attributes atts)
                throws SAXException {
            rootStarted = true;
            super.startElement(uri, localName, qName, atts);
        }
    }
}
