//! `degrau exercise make`: the records and the key, written into a folder. The records
//! carry only `t,u,y`; the key alone says what is hidden.

use std::path::Path;

use crate::ident::challenge::{Level, challenges};
use crate::text::Lang;
use crate::text::exercise::Line;

use super::key::{Key, KeyRecord};
use super::{ExerciseError, MakeArgs, say};

/// The key's file name in the folder.
pub const KEY_FILE: &str = "key.json";

/// `record_01.csv` …, numbered with at least two digits (three past 99).
fn file_name(index: usize, count: usize) -> String {
    let width = if count > 99 { 3 } else { 2 };
    format!("record_{:0width$}.csv", index + 1)
}

fn write(path: &Path, text: &str) -> Result<(), ExerciseError> {
    std::fs::write(path, text).map_err(|source| ExerciseError::Write {
        path: path.display().to_string(),
        source,
    })
}

pub fn run(args: &MakeArgs, lang: Lang) -> Result<(), ExerciseError> {
    let level: Level = args.level.into();
    let count = usize::from(args.count);
    std::fs::create_dir_all(&args.out).map_err(|source| ExerciseError::Write {
        path: args.out.display().to_string(),
        source,
    })?;
    let drawn = challenges(args.seed, count, level);
    let mut records = Vec::with_capacity(count);
    for (i, c) in drawn.iter().enumerate() {
        let file = file_name(i, count);
        write(&args.out.join(&file), &c.csv())?;
        records.push(KeyRecord::new(file, c));
    }
    let key = Key::new(args.seed, level.id(), records);
    let path = args.out.join(KEY_FILE);
    let mut text = serde_json::to_string_pretty(&key).map_err(|e| ExerciseError::Write {
        path: path.display().to_string(),
        source: std::io::Error::other(e),
    })?;
    text.push('\n');
    write(&path, &text)?;
    say(
        &Line::Made {
            count,
            dir: args.out.display().to_string(),
            seed: args.seed,
            level: level.id().to_string(),
        },
        lang,
    )
}

#[cfg(test)]
mod tests {
    use super::file_name;

    #[test]
    fn files_are_numbered_from_one_with_two_or_three_digits() {
        assert_eq!(file_name(0, 5), "record_01.csv");
        assert_eq!(file_name(11, 20), "record_12.csv");
        assert_eq!(file_name(4, 120), "record_005.csv");
    }
}
