//! Build script: give the cdylib a SONAME so that executables linked against
//! `target/<profile>/libhycon.so` by full path record `libhycon.so` in DT_NEEDED, not the
//! absolute build path (CMake links imported libraries by full path).

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if os == "linux" || os == "android" || os.ends_with("bsd") {
        println!("cargo::rustc-cdylib-link-arg=-Wl,-soname,libhycon.so");
    }
}
