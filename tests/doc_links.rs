//! Every relative link in the repository's Markdown (the README, `docs/`, the
//! contracts beside the model, the drivers' and integrations' READMEs) resolves:
//! the file or folder exists, and an anchor (`page.md#section`, `#section`)
//! names a heading of that page, slugged as GitHub renders it. Links to the web
//! (`https:`, `mailto:`) are not followed. Code (fenced blocks and inline spans)
//! is not Markdown, so links and headings inside it do not count.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};

/// Folders that hold no hand-written documentation (build output, git).
const SKIP: [&str; 4] = [".git", "target", "out", "node_modules"];

/// Every `*.md` under `dir`, skipping `SKIP` and hidden folders.
fn markdown_files(dir: &Path, found: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if p.is_dir() {
            if !name.starts_with('.') && !SKIP.iter().any(|s| name.starts_with(s)) {
                markdown_files(&p, found);
            }
        } else if name.ends_with(".md") {
            found.push(p);
        }
    }
}

/// The lines of `text` outside fenced code blocks (the fences dropped too).
fn outside_fences(text: &str) -> impl Iterator<Item = &str> {
    let mut fenced = false;
    text.lines().filter(move |line| {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            return false;
        }
        !fenced
    })
}

/// The text without fenced code blocks and inline code spans.
fn prose(text: &str) -> String {
    let mut out = String::new();
    for line in outside_fences(text) {
        let mut in_code = false;
        for c in line.chars() {
            if c == '`' {
                in_code = !in_code;
            } else if !in_code {
                out.push(c);
            }
        }
        out.push('\n');
    }
    out
}

/// The targets of the inline links `[text](target)` of `text`.
fn link_targets(text: &str) -> Vec<String> {
    let prose = prose(text);
    let mut targets = Vec::new();
    let mut rest = prose.as_str();
    while let Some(at) = rest.find("](") {
        let tail = &rest[at + 2..];
        let end = tail
            .find(|c: char| c == ')' || c.is_whitespace())
            .unwrap_or(tail.len());
        targets.push(tail[..end].to_string());
        rest = &tail[end..];
    }
    targets
}

/// GitHub's anchor of a heading's text: lower case, letters, digits, `-` and
/// `_` kept, spaces become `-`, everything else dropped.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The anchors of a page's headings; a repeated heading gets `-1`, `-2`, ...
/// as on GitHub. Inline code in a heading keeps its text (the backticks go).
fn anchors(text: &str) -> HashSet<String> {
    let mut seen: HashMap<String, usize> = HashMap::new();
    let mut out = HashSet::new();
    for line in outside_fences(text) {
        let hashes = line.chars().take_while(|&c| c == '#').count();
        if hashes == 0 || !line[hashes..].starts_with(' ') {
            continue;
        }
        let base = slug(&line[hashes..]);
        let n = seen.entry(base.clone()).or_insert(0);
        out.insert(if *n == 0 {
            base.clone()
        } else {
            format!("{base}-{n}")
        });
        *n += 1;
    }
    out
}

/// The broken links of the page `page`, as `page: target (why)`.
fn broken_links(page: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(page)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", page.display()));
    let dir = page.parent().expect("a page is in a folder");
    let mut broken = Vec::new();
    for target in link_targets(&text) {
        let scheme = target
            .split_once(':')
            .is_some_and(|(s, _)| !s.is_empty() && s.chars().all(|c| c.is_ascii_alphabetic()));
        if scheme {
            continue;
        }
        let (file, anchor) = match target.split_once('#') {
            Some((f, a)) => (f, Some(a)),
            None => (target.as_str(), None),
        };
        let linked = if file.is_empty() {
            page.to_path_buf()
        } else {
            dir.join(file)
        };
        if !linked.exists() {
            broken.push(format!("{}: {target} (no such file)", page.display()));
            continue;
        }
        if let Some(anchor) = anchor {
            if linked.extension().is_some_and(|e| e == "md") {
                let linked_text = std::fs::read_to_string(&linked).expect("a linked page");
                if !anchors(&linked_text).contains(anchor) {
                    broken.push(format!("{}: {target} (no such heading)", page.display()));
                }
            }
        }
    }
    broken
}

#[test]
fn every_documentation_link_resolves() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut pages = Vec::new();
    markdown_files(root, &mut pages);
    assert!(
        pages.contains(&root.join("README.md")) && pages.contains(&root.join("docs/design.md")),
        "the walk finds the README and the design of record"
    );
    let broken: Vec<String> = pages.iter().flat_map(|p| broken_links(p)).collect();
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

/// The slugs of headings as GitHub renders them (the anchors its pages give).
#[test]
fn slugs_follow_github() {
    assert_eq!(slug(" Quick start"), "quick-start");
    assert_eq!(
        slug("8.1 First-copy delivery (`CTRL.first_copy`, an extension of CiA 701)"),
        "81-first-copy-delivery-ctrlfirst_copy-an-extension-of-cia-701"
    );
    let a = anchors("# Notes\n## Notes\n```\n# not a heading\n```\n#nospace\n");
    let want: HashSet<String> = ["notes", "notes-1"].iter().map(|s| s.to_string()).collect();
    assert_eq!(a, want);
}

/// The check finds a missing file, a missing heading and a missing in-page
/// anchor, and ignores web links and code.
#[test]
fn broken_links_are_found() {
    let dir = std::env::temp_dir().join(format!("drcc-doc-links-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("other.md"), "# Present heading\n").unwrap();
    let page = dir.join("page.md");
    std::fs::write(
        &page,
        "# Top\n[a](other.md#present-heading) [b](missing.md) [c](other.md#absent)\n\
         [d](#top) [e](#nowhere) [f](https://example.com/x) `[g](code.md)`\n\
         ```\n[h](fenced.md)\n```\n",
    )
    .unwrap();
    let broken = broken_links(&page);
    std::fs::remove_dir_all(&dir).unwrap();
    let shown: Vec<&str> = broken
        .iter()
        .map(|b| b.rsplit_once(": ").unwrap().1)
        .collect();
    assert_eq!(
        shown,
        [
            "missing.md (no such file)",
            "other.md#absent (no such heading)",
            "#nowhere (no such heading)"
        ]
    );
}
