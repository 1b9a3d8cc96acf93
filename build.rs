//! Lists the presets in species/ and the stories in species/stories/ for `include_str!`, so that
//! a new file there is a new preset or story.
//!
//! The generated table names each file relative to the crate being compiled
//! (`concat!(env!("CARGO_MANIFEST_DIR"), …)`), never by this script's absolute path, so a
//! checkout moved or copied with its build cache reads its own files, and an edit to one is
//! seen by the compiler's own tracking of included files.

use std::fmt::Write;
use std::path::Path;

fn main() {
    let manifest = std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    // Relative to the package: a new or removed file there (or in stories/) lists them again.
    println!("cargo:rerun-if-changed=species");
    let out = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    let presets = table(
        &manifest,
        "species",
        "PRESET_FILES",
        "every file in species/",
    );
    std::fs::write(Path::new(&out).join("species.rs"), presets).expect("write species table");
    let stories = table(
        &manifest,
        "species/stories",
        "STORY_FILES",
        "every story in species/stories/",
    );
    std::fs::write(Path::new(&out).join("stories.rs"), stories).expect("write story table");
}

/// The constant `name`: (id, JSON) of every JSON file in the folder `folder` of the package.
fn table(manifest: &std::ffi::OsStr, folder: &str, name: &str, what: &str) -> String {
    let dir = Path::new(manifest).join(folder);
    let mut ids: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{folder}/ is not readable: {e}"))
        .map(|e| e.expect("readable species/ entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .map(|p| {
            p.file_stem()
                .and_then(|s| s.to_str())
                .expect("UTF-8 file name")
                .to_string()
        })
        .collect();
    ids.sort();
    let mut out = format!("/// (id, JSON) of {what}.\npub const {name}: &[(&str, &str)] = &[\n");
    for id in ids {
        writeln!(
            out,
            "    ({id:?}, include_str!(concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/{folder}/{id}.json\"))),"
        )
        .expect("write to string");
    }
    out.push_str("];\n");
    out
}
