//! Build script.
//!
//! * Always: give the cdylib a SONAME so that executables linked against
//!   `target/<profile>/libhycon.so` by full path record `libhycon.so` in DT_NEEDED, not the
//!   absolute build path (CMake links imported libraries by full path).
//! * Feature `suitesparse` only: generate Rust bindings for CHOLMOD's `cholmod.h` with bindgen
//!   (into `$OUT_DIR/cholmod_bindings.rs`) and link `libcholmod`. Without the feature nothing
//!   else runs (bindgen is not even compiled).
//!
//! Debian's libsuitesparse-dev ships neither a pkg-config file nor a CMake config for CHOLMOD,
//! so the header is looked up in `$CHOLMOD_INCLUDE_DIR`, then `/usr/include/suitesparse`, then
//! `/usr/include`; `$CHOLMOD_LIB_DIR`, if set, is added to the library search path.

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if os == "linux" || os == "android" || os.ends_with("bsd") {
        println!("cargo::rustc-cdylib-link-arg=-Wl,-soname,libhycon.so");
    }
    #[cfg(feature = "suitesparse")]
    cholmod::generate();
}

#[cfg(feature = "suitesparse")]
mod cholmod {
    use std::path::PathBuf;

    /// Run bindgen on cholmod.h (the `cholmod_l_*` int64 interface and the structs and
    /// constants it needs) and emit the link flags.
    pub fn generate() {
        println!("cargo::rerun-if-env-changed=CHOLMOD_INCLUDE_DIR");
        println!("cargo::rerun-if-env-changed=CHOLMOD_LIB_DIR");
        let candidates: Vec<PathBuf> = std::env::var_os("CHOLMOD_INCLUDE_DIR")
            .map(PathBuf::from)
            .into_iter()
            .chain(["/usr/include/suitesparse", "/usr/include"].map(PathBuf::from))
            .collect();
        let Some(dir) = candidates.iter().find(|d| d.join("cholmod.h").is_file()) else {
            panic!(
                "feature `suitesparse`: cholmod.h not found in {candidates:?}; install \
                 libsuitesparse-dev (Debian/Ubuntu) or set CHOLMOD_INCLUDE_DIR"
            );
        };
        let header = dir.join("cholmod.h");
        println!("cargo::rerun-if-changed={}", header.display());
        if let Some(lib) = std::env::var_os("CHOLMOD_LIB_DIR") {
            println!(
                "cargo::rustc-link-search=native={}",
                PathBuf::from(lib).display()
            );
        }
        println!("cargo::rustc-link-lib=cholmod");

        let bindings = bindgen::Builder::default()
            .header(header.to_string_lossy())
            .clang_arg(format!("-I{}", dir.display()))
            .allowlist_function(
                "cholmod_l_(start|finish|allocate_sparse|free_sparse|analyze_p|factorize|\
                 free_factor|solve2|free_dense)",
            )
            .allowlist_type("cholmod_(common|sparse|factor|dense)(_struct)?")
            .allowlist_var("CHOLMOD_.*")
            .layout_tests(true)
            .derive_default(false)
            .generate_comments(false)
            .generate()
            .unwrap_or_else(|e| panic!("bindgen failed on {}: {e}", header.display()));
        let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR is set by cargo"));
        bindings
            .write_to_file(out.join("cholmod_bindings.rs"))
            .expect("write cholmod_bindings.rs");
    }
}
