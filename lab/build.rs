//! Build script of hycon-lab.
//!
//! Feature `fclib` only: generate Rust bindings for FCLIB's `fclib.h` and the few serial-HDF5
//! calls `hycon_lab::fclib` checks a file with before libfclib reads it (into
//! `$OUT_DIR/fclib_bindings.rs`), and link `libfclib` and the serial HDF5 libraries. Without
//! the feature nothing runs (bindgen is not even compiled).
//!
//! The libraries are linked by name, not through pkg-config: Debian's `fclib.pc` requires
//! `hdf5`, which can resolve to an MPI build of HDF5 (PETSc's) while `libfclib.so` is linked
//! against the serial one. The headers are looked up in `$FCLIB_INCLUDE_DIR` (default
//! `/usr/include`) and `$HDF5_INCLUDE_DIR` (default `/usr/include/hdf5/serial`, Debian's
//! serial HDF5, else `/usr/include`); `$FCLIB_LIB_DIR`, if set, is added to the library search
//! path. With Debian's serial headers the HDF5 libraries are `hdf5_serial` and
//! `hdf5_serial_hl`, elsewhere `hdf5` and `hdf5_hl`.

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    #[cfg(feature = "fclib")]
    fclib::generate();
}

#[cfg(feature = "fclib")]
mod fclib {
    use std::path::PathBuf;

    /// The first of `$var` and `defaults` that holds `header`.
    fn include_dir(var: &str, defaults: &[&str], header: &str) -> PathBuf {
        println!("cargo::rerun-if-env-changed={var}");
        let candidates: Vec<PathBuf> = std::env::var_os(var)
            .map(PathBuf::from)
            .into_iter()
            .chain(defaults.iter().map(PathBuf::from))
            .collect();
        match candidates.iter().find(|d| d.join(header).is_file()) {
            Some(dir) => dir.clone(),
            None => panic!(
                "feature `fclib`: {header} not found in {candidates:?}; install libfclib-dev \
                 (Debian/Ubuntu; it brings libhdf5-dev) or set {var}"
            ),
        }
    }

    /// Run bindgen on fclib.h and hdf5.h (the calls and structs `hycon_lab::fclib` uses) and
    /// emit the link flags.
    pub fn generate() {
        let fclib = include_dir("FCLIB_INCLUDE_DIR", &["/usr/include"], "fclib.h");
        let hdf5 = include_dir(
            "HDF5_INCLUDE_DIR",
            &["/usr/include/hdf5/serial", "/usr/include"],
            "hdf5.h",
        );
        println!("cargo::rerun-if-env-changed=FCLIB_LIB_DIR");
        if let Some(lib) = std::env::var_os("FCLIB_LIB_DIR") {
            println!(
                "cargo::rustc-link-search=native={}",
                PathBuf::from(lib).display()
            );
        }
        let serial = hdf5.ends_with("hdf5/serial");
        println!("cargo::rustc-link-lib=fclib");
        for lib in ["hdf5", "hdf5_hl"] {
            let lib = if serial {
                lib.replacen("hdf5", "hdf5_serial", 1)
            } else {
                lib.to_string()
            };
            println!("cargo::rustc-link-lib={lib}");
        }

        let wrapper = "#include <fclib.h>\n#include <hdf5.h>\n#include <hdf5_hl.h>\n";
        let bindings = bindgen::Builder::default()
            .header_contents("fclib_wrapper.h", wrapper)
            .clang_arg(format!("-I{}", fclib.display()))
            .clang_arg(format!("-I{}", hdf5.display()))
            .allowlist_function(
                "fclib_(write_local|write_solution|read_local|read_solution|delete_local|\
                 delete_solutions|merit_local)",
            )
            .allowlist_function(
                "H5(Eset_auto2|Fis_hdf5|Fopen|Fclose|Lexists|LTget_dataset_ndims|\
                 LTget_dataset_info|LTread_dataset_int)",
            )
            .allowlist_type("fclib_(local|matrix|matrix_info|info|solution|merit)")
            .allowlist_type("H5T_class_t")
            .layout_tests(true)
            .derive_default(false)
            .generate_comments(false)
            .generate()
            .unwrap_or_else(|e| panic!("bindgen failed on fclib.h and hdf5.h: {e}"));
        let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR is set by cargo"));
        bindings
            .write_to_file(out.join("fclib_bindings.rs"))
            .expect("write fclib_bindings.rs");
    }
}
