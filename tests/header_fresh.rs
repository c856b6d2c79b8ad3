//! The committed C header `include/hycon.h` must be what cbindgen generates for the crate with
//! `cbindgen.toml`. Regenerate with `HYCON_BLESS=1 cargo test --test header_fresh` (or the
//! cbindgen 0.29.4 CLI: `cbindgen --config cbindgen.toml --crate hycon --output include/hycon.h`).

use std::path::Path;

fn generate() -> Vec<u8> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config =
        cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("read cbindgen.toml");
    let mut fresh = Vec::new();
    cbindgen::Builder::new()
        .with_config(config)
        .with_crate(dir)
        .generate()
        .expect("cbindgen failed on the crate")
        .write(&mut fresh);
    fresh
}

#[test]
fn committed_header_is_fresh() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("include/hycon.h");
    let fresh = generate();
    let committed = std::fs::read(&path).unwrap_or_default();
    if fresh == committed {
        return;
    }
    if std::env::var_os("HYCON_BLESS").is_some() {
        std::fs::write(&path, &fresh).expect("write include/hycon.h");
        eprintln!("rewrote {}", path.display());
        return;
    }
    let fresh = String::from_utf8_lossy(&fresh);
    let committed = String::from_utf8_lossy(&committed);
    let first = fresh
        .lines()
        .zip(committed.lines())
        .position(|(a, b)| a != b)
        .unwrap_or_else(|| fresh.lines().count().min(committed.lines().count()));
    panic!(
        "include/hycon.h is stale (first difference at line {}):\n  generated: {:?}\n  committed: {:?}\n\
         regenerate with `HYCON_BLESS=1 cargo test --test header_fresh` and commit it",
        first + 1,
        fresh.lines().nth(first).unwrap_or("<end of file>"),
        committed.lines().nth(first).unwrap_or("<end of file>"),
    );
}

/// The version macros in the header equal the package version (the single source).
#[test]
fn header_version_macros_match_package_version() {
    let header =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/hycon.h"))
            .expect("read include/hycon.h");
    let define = |name: &str| -> i64 {
        let prefix = format!("#define {name} ");
        let line = header
            .lines()
            .find(|l| l.starts_with(&prefix))
            .unwrap_or_else(|| panic!("no `{prefix}` in include/hycon.h"));
        line[prefix.len()..].trim().parse().expect("integer macro")
    };
    let part = |s: &str| -> i64 { s.parse().unwrap() };
    let (major, minor, patch) = (
        part(env!("CARGO_PKG_VERSION_MAJOR")),
        part(env!("CARGO_PKG_VERSION_MINOR")),
        part(env!("CARGO_PKG_VERSION_PATCH")),
    );
    assert_eq!(define("HYCON_VERSION_MAJOR"), major);
    assert_eq!(define("HYCON_VERSION_MINOR"), minor);
    assert_eq!(define("HYCON_VERSION_PATCH"), patch);
    assert_eq!(define("HYCON_VERSION"), major * 10000 + minor * 100 + patch);
}
