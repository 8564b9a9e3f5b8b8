//! The reference model is the oracle: it must be written from the standard and
//! the timing contract, never from the HDL. No file under `cosim/src/model` may
//! mention the HDL crates.

use std::path::Path;

fn visit(dir: &Path, files: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("read model dir") {
        let path = entry.expect("dir entry").path();
        if path.is_dir() {
            visit(&path, files);
        } else {
            files.push(path);
        }
    }
}

#[test]
fn model_sources_do_not_mention_the_hdl() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("src")
        .join("model");
    let mut files = Vec::new();
    visit(&root, &mut files);
    assert!(files.len() >= 4, "model sources found: {files:?}");
    // Spelled in pieces so that this file could live in the model folder too.
    let banned = [["drcc", "_hdl"].concat(), ["rust", "_hdl"].concat()];
    for file in &files {
        let text = std::fs::read_to_string(file).expect("read model source");
        for word in &banned {
            assert!(
                !text.contains(word.as_str()),
                "{} mentions `{word}`",
                file.display()
            );
        }
    }
}
