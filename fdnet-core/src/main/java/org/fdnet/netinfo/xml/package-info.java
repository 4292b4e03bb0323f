/**
 * The repository: .fdn network definitions and .fdg graphic side files on disk.
 *
 * <pre>
 *   file bytes ──DoctypeSupplier (adds a DOCTYPE if missing)──▶ GuardedXmlReader
 *        validating SAX parser ── bundled DTD only (BundledDtd), entity declarations refused,
 *        declared encoding honoured, every error collected with its position
 *        ──JAXB──▶ binding.* elements (with positions)
 *                    ├─▶ NetworkFileReader: model rules via NetworkInfo edits ─▶ NetworkInfo / NetworkDocument
 *                    └─▶ LayoutRepository: numbers, colours, duplicates       ─▶ NetworkLayout
 *   NetworkInfo ──NetworkFileWriter (canonical form)──▶ XmlFragments ──▶ AtomicFile (temp file + move)
 * </pre>
 *
 * Every problem is a {@link org.fdnet.netinfo.xml.Problem} printed {@code file:line:col: message}; a file
 * with problems yields a {@link org.fdnet.netinfo.xml.NetworkFileException} and no model. For every valid
 * file, load → save → load is the identity on the model.
 */
package org.fdnet.netinfo.xml;
