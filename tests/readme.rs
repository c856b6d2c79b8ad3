//! The C code blocks of README.md and of the guide's pages (`docs/*.md`) compile against the
//! committed header (C99, warnings as errors), so the documented examples stay true to the API.

use std::path::Path;
use std::process::Command;

/// The ```c blocks of a Markdown page.
fn c_blocks(readme: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut current: Option<String> = None;
    for line in readme.lines() {
        match (&mut current, line.trim_end()) {
            (None, "```c") => current = Some(String::new()),
            (Some(_), "```") => blocks.extend(current.take()),
            (Some(block), text) => {
                block.push_str(text);
                block.push('\n');
            }
            (None, _) => {}
        }
    }
    blocks
}

#[test]
fn readme_c_examples_compile() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let blocks = c_blocks(&readme);
    assert!(
        blocks.len() >= 3,
        "expected the element, model and host examples"
    );
    compile_all("README", &blocks);
}

#[test]
fn guide_c_examples_compile() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut pages: Vec<_> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    pages.sort();
    let mut total = 0;
    for page in &pages {
        let blocks = c_blocks(&std::fs::read_to_string(page).unwrap());
        total += blocks.len();
        let name = page
            .strip_prefix(root)
            .unwrap_or(page)
            .display()
            .to_string();
        compile_all(&name, &blocks);
    }
    assert!(
        total >= 5,
        "expected the host guide's and the elements page's C examples, found {total}"
    );
}

/// Compile every block with `cc -std=c99 -Wall -Wextra -Werror -pedantic -fsyntax-only`.
fn compile_all(page: &str, blocks: &[String]) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let tag: String = page
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    let dir = std::env::temp_dir().join(format!("hycon-readme-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (i, block) in blocks.iter().enumerate() {
        let file = dir.join(format!("block{i}.c"));
        std::fs::write(&file, block).unwrap();
        let out = Command::new("cc")
            .args([
                "-std=c99",
                "-Wall",
                "-Wextra",
                "-Werror",
                "-pedantic",
                "-fsyntax-only",
            ])
            .arg("-I")
            .arg(root.join("include"))
            .arg(&file)
            .output()
            .expect("a C compiler (cc)");
        assert!(
            out.status.success(),
            "{page} C block {i} does not compile:\n{block}\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
