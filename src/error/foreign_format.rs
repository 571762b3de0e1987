//! Files of a known binary format handed to a command that reads text (a
//! `response.png` given to `metrics`): told by their first bytes (their
//! magic numbers) and named, where the UTF-8 check would only ask whether
//! the file was saved as Latin-1.

/// A binary format told by its first bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ForeignFormat {
    /// A PNG image (`simulate` writes `response.png`).
    Png,
    /// A JPEG image.
    Jpeg,
    /// A GIF image.
    Gif,
    /// A PDF document.
    Pdf,
    /// A ZIP archive (an `.xlsx` workbook is one).
    Zip,
    /// A gzip-compressed file.
    Gzip,
}

impl ForeignFormat {
    /// The format whose magic number `head` starts with, if any.
    pub fn of(head: &[u8]) -> Option<Self> {
        const MAGIC: [(&[u8], ForeignFormat); 7] = [
            (b"\x89PNG\r\n\x1a\n", ForeignFormat::Png),
            (b"\xff\xd8\xff", ForeignFormat::Jpeg),
            (b"GIF87a", ForeignFormat::Gif),
            (b"GIF89a", ForeignFormat::Gif),
            (b"%PDF-", ForeignFormat::Pdf),
            (b"PK\x03\x04", ForeignFormat::Zip),
            (b"\x1f\x8b", ForeignFormat::Gzip),
        ];
        MAGIC
            .iter()
            .find(|(magic, _)| head.starts_with(magic))
            .map(|(_, f)| *f)
    }

    /// The file as a noun phrase.
    pub fn what(self) -> &'static str {
        match self {
            ForeignFormat::Png => "a PNG image",
            ForeignFormat::Jpeg => "a JPEG image",
            ForeignFormat::Gif => "a GIF image",
            ForeignFormat::Pdf => "a PDF document",
            ForeignFormat::Zip => {
                "a ZIP archive (an .xlsx workbook is one: export the sheet as CSV)"
            }
            ForeignFormat::Gzip => "a gzip-compressed file (unpack it first)",
        }
    }
}
