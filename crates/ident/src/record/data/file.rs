//! File access: a regular file read whole within the size cap (directories, FIFOs, devices
//! and sockets refused before they are opened), the size check of bytes and text, and the
//! decoding of a file's bytes (UTF-8, UTF-16 with BOM, else Latin-1; a zero byte is binary).

use std::borrow::Cow;
use std::fs::{FileType, Metadata};
use std::io::Read;
use std::path::Path;

use super::{DataError, DataNote, FileKind, MAX_FILE_BYTES, Source};

/// The bytes of a regular file of at most [`MAX_FILE_BYTES`].
pub(super) fn read_capped(path: &Path) -> Result<Vec<u8>, DataError> {
    let shown = || path.display().to_string();
    let io = |e: std::io::Error| DataError::Io {
        path: shown(),
        kind: e.kind(),
        reason: e.to_string(),
    };
    // Checked before opening, then again on the file opened (had the path been replaced).
    check_regular(&shown, &std::fs::metadata(path).map_err(io)?)?;
    let file = std::fs::File::open(path).map_err(io)?;
    let metadata = file.metadata().map_err(io)?;
    check_regular(&shown, &metadata)?;
    let expected = usize::try_from(metadata.len()).unwrap_or(0);
    let mut bytes = Vec::with_capacity(expected.saturating_add(1));
    // A file growing while it is read stops one byte past the cap.
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    check_size(Source::File, bytes.len())?;
    Ok(bytes)
}

/// A regular file within the size cap, from its metadata.
fn check_regular(shown: &dyn Fn() -> String, metadata: &Metadata) -> Result<(), DataError> {
    if let Some(kind) = special_kind(&metadata.file_type()) {
        return Err(DataError::NotAFile {
            path: shown(),
            kind,
        });
    }
    if metadata.len() > MAX_FILE_BYTES {
        return Err(DataError::TooLarge {
            what: Source::File,
            size: metadata.len(),
        });
    }
    Ok(())
}

/// What a file that is not a regular file is, in words; `None` for a regular file.
fn special_kind(file_type: &FileType) -> Option<FileKind> {
    if file_type.is_file() {
        return None;
    }
    if file_type.is_dir() {
        return Some(FileKind::Directory);
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_fifo() {
            return Some(FileKind::NamedPipe);
        }
        if file_type.is_char_device() || file_type.is_block_device() {
            return Some(FileKind::Device);
        }
        if file_type.is_socket() {
            return Some(FileKind::Socket);
        }
    }
    Some(FileKind::Special)
}

/// Text (or bytes) of at most [`MAX_FILE_BYTES`].
pub(super) fn check_size(what: Source, len: usize) -> Result<(), DataError> {
    let len = u64::try_from(len).unwrap_or(u64::MAX);
    if len > MAX_FILE_BYTES {
        return Err(DataError::TooLarge { what, size: len });
    }
    Ok(())
}

/// Decodes a file's bytes; the note says when it was not UTF-8.
pub(super) fn decode(bytes: &[u8]) -> Result<(Cow<'_, str>, Option<DataNote>), DataError> {
    let utf16 = |rest: &[u8], unit: fn([u8; 2]) -> u16| {
        let units = rest.chunks_exact(2).map(|c| unit([c[0], c[1]]));
        let text: String = char::decode_utf16(units)
            .map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER))
            .collect();
        (Cow::Owned(text), Some(DataNote::Utf16))
    };
    if let Some(rest) = bytes.strip_prefix(&[0xFF, 0xFE]) {
        return Ok(utf16(rest, u16::from_le_bytes));
    }
    if let Some(rest) = bytes.strip_prefix(&[0xFE, 0xFF]) {
        return Ok(utf16(rest, u16::from_be_bytes));
    }
    if let Some(zero) = bytes.iter().position(|&b| b == 0) {
        let line = 1 + bytes.iter().take(zero).filter(|&&b| b == b'\n').count();
        return Err(DataError::Binary { line });
    }
    Ok(match std::str::from_utf8(bytes) {
        Ok(text) => (Cow::Borrowed(text), None),
        Err(_) => (
            Cow::Owned(bytes.iter().map(|&b| char::from(b)).collect()),
            Some(DataNote::Latin1),
        ),
    })
}
