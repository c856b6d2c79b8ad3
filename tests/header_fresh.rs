//! The committed C header `include/hycon.h` must be what cbindgen generates for the crate with
//! `cbindgen.toml`. Regenerate with `HYCON_BLESS=1 cargo test --test integration header_fresh::` (or the
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
         regenerate with `HYCON_BLESS=1 cargo test --test integration header_fresh::` and commit it",
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

/// Every name the header declares (macros, types, struct tags, functions, function-pointer
/// typedefs, constants) carries the prefix `hycon_`, `Hycon` or `HYCON_`: a public item of another
/// module that cbindgen picks up (it did with `MAX_CORNERS` and `SCALE_RANGE`) must be excluded
/// in cbindgen.toml or renamed.
#[test]
fn header_declares_only_prefixed_names() {
    let header =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/hycon.h"))
            .expect("read include/hycon.h");
    let names = declared_names(&header);
    assert!(
        names.contains(&"hycon_contact_displacement".to_string()),
        "{names:?}"
    );
    assert!(
        names.contains(&"HyconElementBlock".to_string()),
        "{names:?}"
    );
    assert!(names.contains(&"HYCON_OK".to_string()), "{names:?}");
    let prefixed =
        |n: &str| n.starts_with("hycon_") || n.starts_with("Hycon") || n.starts_with("HYCON_");
    let bad: Vec<&String> = names.iter().filter(|n| !prefixed(n)).collect();
    assert!(
        bad.is_empty(),
        "unprefixed names in include/hycon.h: {bad:?}"
    );
    // the check itself sees an unprefixed macro, type and function
    let planted = "#define MAX_CORNERS 4\ntypedef int32_t Kind;\n#ifdef __cplusplus\nextern \"C\" {\n\
                   #endif\nint f(void);\n#ifdef __cplusplus\n}\n#endif\n";
    assert_eq!(declared_names(planted), ["Kind", "MAX_CORNERS", "f"]);
}

/// The names a C header declares at file scope (comments and preprocessor conditionals aside).
fn declared_names(header: &str) -> Vec<String> {
    // drop comments
    let mut text = String::new();
    let mut rest = header;
    while let Some(i) = rest.find("/*") {
        text.push_str(&rest[..i]);
        rest = &rest[i + 2..];
        rest = &rest[rest.find("*/").map_or(rest.len(), |j| j + 2)..];
    }
    text.push_str(rest);
    let text: String = text
        .lines()
        .map(|l| l.find("//").map_or(l, |i| &l[..i]))
        .collect::<Vec<_>>()
        .join("\n");
    let ident = |s: &str| -> Option<String> {
        let s = s.trim_start();
        let end = s
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(s.len());
        (end > 0).then(|| s[..end].to_string())
    };
    let mut names = Vec::new();
    let mut code = String::new();
    let mut cplusplus = false; // inside `#ifdef __cplusplus` (the `extern "C"` braces)
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with("#ifdef __cplusplus") {
            cplusplus = true;
        } else if t.starts_with("#endif") {
            cplusplus = false;
        } else if cplusplus {
        } else if let Some(d) = t.strip_prefix("#define") {
            names.extend(ident(d));
        } else if !t.starts_with('#') {
            code.push_str(line);
            code.push('\n');
        }
    }
    // file-scope statements: split at `;` and at braces of depth 0
    let mut depth = 0usize;
    let mut statement = String::new();
    let mut statements = Vec::new();
    for c in code.chars() {
        match c {
            '{' => {
                if depth == 0 {
                    statement.push('{');
                }
                depth += 1;
            }
            '}' => depth = depth.saturating_sub(1),
            ';' if depth == 0 => statements.push(std::mem::take(&mut statement)),
            _ if depth == 0 => statement.push(c),
            _ => {}
        }
    }
    let keywords = [
        "typedef", "struct", "enum", "union", "const", "extern", "static",
    ];
    for s in statements {
        let s = s.split_whitespace().collect::<Vec<_>>().join(" ");
        if s.is_empty() || s.starts_with("extern \"C\"") {
            continue;
        }
        for tag in ["struct ", "enum ", "union "] {
            for part in s.split(tag).skip(1) {
                if let Some(n) = ident(part).filter(|n| !keywords.contains(&n.as_str())) {
                    names.push(n);
                }
            }
        }
        if let Some(i) = s.find("(*") {
            names.extend(ident(&s[i + 2..])); // function pointer typedef
        } else if let Some(i) = s.find('(') {
            // function: the identifier before the first parenthesis
            let head = s[..i].trim_end();
            let start = head
                .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .map_or(0, |j| j + 1);
            names.push(head[start..].to_string());
        } else if s.starts_with("typedef") {
            let head = s.trim_end_matches([' ', '{']);
            let start = head
                .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .map_or(0, |j| j + 1);
            names.push(head[start..].to_string());
        }
    }
    names.sort();
    names.dedup();
    names
}
