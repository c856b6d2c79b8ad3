//! The committed header `include/hycon.h` against the Rust definitions of the C ABI.
//!
//! At test time bindgen (libclang) parses the header back into Rust source, with its layout
//! assertions: the sizes, alignments and field offsets clang computed for every struct. The
//! source is read as text (a Rust test cannot `include!` a file generated while it runs): a small
//! tokenizer finds the structs with their fields and field types, the type aliases, the
//! `HYCON_*` constants and the layout numbers. The system C compiler (the one C hosts use) then
//! compiles a generated program that prints `sizeof`, `_Alignof`, `offsetof` and the size of every
//! field of every struct bindgen found, and the value of every constant. Both are compared with
//! the Rust side: `size_of`, `align_of`, `offset_of!` and the field types of the `#[repr(C)]` types
//! of `hycon::ffi`, and the values of its constants.
//!
//! Completeness, both ways: a struct, type alias or `HYCON_*` constant in the header that this
//! test does not list fails it, and so does a `#[repr(C)]` struct, `pub type Hycon*` or
//! `pub const HYCON_*` in `src/ffi/*.rs` that it does not list (so a type added later must be
//! added here). The field lists below are checked to be exhaustive at compile time.
//!
//! `HYCON_LAYOUT_HEADER=<path>` checks another header instead of the committed one (for trying a
//! hand-edited copy); `layout_check_catches_mismatches` proves on edited copies that a changed
//! field type, a changed constant and an unlisted struct are caught.

use hycon::ffi::*;
use std::collections::{BTreeMap, BTreeSet};
use std::ffi::c_void;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

// ------------------------------------------------------------------------------------------
// The Rust side

/// A C type as both sides spell it, in one canonical form: primitives by their Rust name
/// (`f64`, `i32`, `usize`, ...), `c_void`, struct names, `*mut T` / `*const T`, `[T; N]`, and
/// nullable function pointers `Option<fn(A, B) -> R>`.
trait Describe {
    fn describe() -> String;
}

macro_rules! describe_as {
    ($($t:ty => $s:expr),* $(,)?) => {
        $(impl Describe for $t {
            fn describe() -> String {
                $s.to_string()
            }
        })*
    };
}

describe_as! {
    () => "()",
    f32 => "f32", f64 => "f64",
    i8 => "i8", i16 => "i16", i32 => "i32", i64 => "i64", isize => "isize",
    u8 => "u8", u16 => "u16", u32 => "u32", u64 => "u64", usize => "usize",
    c_void => "c_void",
}

impl<T: Describe> Describe for *mut T {
    fn describe() -> String {
        format!("*mut {}", T::describe())
    }
}

impl<T: Describe> Describe for *const T {
    fn describe() -> String {
        format!("*const {}", T::describe())
    }
}

impl<T: Describe, const N: usize> Describe for [T; N] {
    fn describe() -> String {
        format!("[{}; {N}]", T::describe())
    }
}

macro_rules! describe_fn_pointers {
    ($(($($arg:ident),*)),* $(,)?) => {
        $(impl<R: Describe, $($arg: Describe),*> Describe
            for Option<unsafe extern "C" fn($($arg),*) -> R>
        {
            fn describe() -> String {
                let args: Vec<String> = vec![$($arg::describe()),*];
                format!("Option<fn({}) -> {}>", args.join(", "), R::describe())
            }
        })*
    };
}

describe_fn_pointers!((), (A), (A, B), (A, B, C), (A, B, C, D), (A, B, C, D, E));

/// Layout of one field on the Rust side.
struct RustField {
    name: &'static str,
    offset: usize,
    size: usize,
    ty: String,
}

/// Layout of one `#[repr(C)]` struct on the Rust side.
struct RustStruct {
    name: &'static str,
    size: usize,
    align: usize,
    fields: Vec<RustField>,
}

fn size_of_pointee<F>(_: *const F) -> usize {
    std::mem::size_of::<F>()
}

fn describe_pointee<F: Describe>(_: *const F) -> String {
    F::describe()
}

/// The `#[repr(C)]` structs of `hycon::ffi`, each with all its fields in declaration order (the
/// destructuring pattern fails to compile if a field is missing from a list): their `Describe`
/// and `fn rust_structs()`, their layouts on the Rust side.
macro_rules! rust_structs {
    ($($ty:ident { $($field:ident),* $(,)? }),* $(,)?) => {
        $(impl Describe for $ty {
            fn describe() -> String {
                stringify!($ty).to_string()
            }
        }

        const _: fn(&$ty) = |v: &$ty| {
            let $ty { $($field: _),* } = v;
        };)*

        fn rust_structs() -> Vec<RustStruct> {
            vec![$({
                let value = std::mem::MaybeUninit::<$ty>::uninit();
                let base = value.as_ptr();
                RustStruct {
                    name: stringify!($ty),
                    size: std::mem::size_of::<$ty>(),
                    align: std::mem::align_of::<$ty>(),
                    fields: vec![$(RustField {
                        name: stringify!($field),
                        offset: std::mem::offset_of!($ty, $field),
                        // SAFETY: a raw pointer to a field of (uninitialised) local storage; it
                        // is never read or turned into a reference.
                        size: size_of_pointee(unsafe { &raw const (*base).$field }),
                        ty: describe_pointee(unsafe { &raw const (*base).$field }),
                    }),*],
                }
            }),*]
        }
    };
}

rust_structs! {
    HyconMaterial { youngs, poisson, thickness, analysis },
    HyconSolidMaterial { youngs, poisson },
    HyconShapeReport { integration_jacobian, corner_jacobian, warp_degrees, corner, face, warnings },
    HyconContactOptions {
        size,
        tolerance,
        gap_tolerance,
        tension_tolerance,
        friction_tolerance,
        slip_tolerance,
        search_distance,
        max_iterations,
        lock_rounds,
        backend,
        kinematics,
        threads,
        monitor,
        monitor_data,
        cutback_depth,
        cutback_min_fraction,
    },
    HyconIterationRecord {
        increment,
        iteration,
        active,
        stick,
        slip,
        changes,
        r,
        condition,
        violation,
        sub_increment,
    },
    HyconIncrementInfo { increment, iterations, active, slip, sub_increments, cutbacks },
    HyconNodeResult {
        node,
        state,
        slip_sign,
        tn,
        ts,
        normal,
        tangent,
        position,
        weight,
        gap,
        force,
    },
    HyconBNodeResult { node, weight, force, pressure, position },
    HyconContactNode { node, weight, coverage, normal, tangent, gap, normal_gap },
    HyconCouplingEntry { row, node, side, value },
    HyconConstraintEntry { row, column, value },
    HyconElementBlock { offsets, nodes, n_elements, materials, kind },
    HyconPolyline { nodes, n },
    HyconHostNodes { ids, coords, equations, n },
    HyconCondensed { size, kind, m, equations, matrix },
    HyconTimings { assembly, factorization, flexibility, load_solves, iterations, recovery },
    HyconBrickBlock { nodes, n_elements, materials, kind },
    HyconBrickFaces { faces, n },
    HyconSolidNodeResult {
        node,
        state,
        tn,
        ts,
        slip_direction,
        normal,
        tangent,
        position,
        weight,
        gap,
        force,
    },
    HyconSolidBNodeResult { node, weight, force, pressure, position },
    HyconSolidContactNode { node, weight, coverage, normal, tangent, gap, normal_gap },
    HyconSolidHostNodes { ids, coords, equations, n },
    HyconHostFaces { nodes, n },
}

/// The opaque handle types: declared but not defined in the header, no layout to check.
const OPAQUE: &[&str] = &[
    "HyconContact",
    "HyconHost",
    "HyconModel",
    "HyconSolidContact",
    "HyconSolidHost",
    "HyconSolidModel",
];

macro_rules! aliases {
    ($($name:ident),* $(,)?) => {
        vec![$((stringify!($name), <$name as Describe>::describe())),*]
    };
}

/// The type aliases of `hycon::ffi` (`pub type Hycon*`) as the types they stand for.
fn rust_aliases() -> BTreeMap<&'static str, String> {
    aliases![
        HyconStatus,
        HyconElementKind,
        HyconAnalysis,
        HyconBackend,
        HyconKinematics,
        HyconDirections,
        HyconNodeState,
        HyconSide,
        HyconTriangle,
        HyconPlateControl,
        HyconCondensedKind,
        HyconMonitorFn,
        HyconSolveFn,
        HyconBrickKind,
        HyconShapePolicy,
    ]
    .into_iter()
    .collect()
}

macro_rules! constants {
    ($($name:ident),* $(,)?) => {
        vec![$((stringify!($name), $name as i128)),*]
    };
}

/// Every `HYCON_*` constant of `hycon::ffi` with its value.
fn rust_constants() -> BTreeMap<&'static str, i128> {
    constants![
        HYCON_VERSION_MAJOR,
        HYCON_VERSION_MINOR,
        HYCON_VERSION_PATCH,
        HYCON_VERSION,
        HYCON_MAX_NODES,
        HYCON_MAX_DOF,
        HYCON_MAX_BETA,
        HYCON_BRICK_NODES,
        HYCON_BRICK_DOF,
        HYCON_BRICK_MAX_BETA,
        HYCON_BRICK_HYBRID18,
        HYCON_BRICK_H8,
        HYCON_SHAPE_INTEGRATION_POINTS,
        HYCON_SHAPE_STRICT,
        HYCON_SHAPE_CORNER_JACOBIAN,
        HYCON_SHAPE_WARPED_FACE,
        HYCON_FIXED,
        HYCON_OK,
        HYCON_ERROR_NULL_POINTER,
        HYCON_ERROR_INVALID_ARGUMENT,
        HYCON_ERROR_INVALID_MATERIAL,
        HYCON_ERROR_BAD_ELEMENT,
        HYCON_ERROR_SINGULAR,
        HYCON_ERROR_SOLVER,
        HYCON_ERROR_BUFFER_TOO_SMALL,
        HYCON_ERROR_CONTACT,
        HYCON_ERROR_CALLBACK,
        HYCON_ERROR_PANIC,
        HYCON_WARNING_SHAPE,
        HYCON_ELEMENT_HYBRID,
        HYCON_ELEMENT_PIAN_SUMIHARA,
        HYCON_ELEMENT_Q4,
        HYCON_PLANE_STRAIN,
        HYCON_PLANE_STRESS,
        HYCON_AXISYMMETRIC,
        HYCON_BACKEND_FAER,
        HYCON_BACKEND_CHOLMOD,
        HYCON_KINEMATICS_SMALL,
        HYCON_KINEMATICS_FINITE,
        HYCON_MAX_THREADS,
        HYCON_MAX_CUTBACK_DEPTH,
        HYCON_X,
        HYCON_Y,
        HYCON_XY,
        HYCON_Z,
        HYCON_XYZ,
        HYCON_NODE_OPEN,
        HYCON_NODE_STICK,
        HYCON_NODE_SLIP,
        HYCON_NODE_FRICTIONLESS,
        HYCON_SIDE_A,
        HYCON_SIDE_B,
        HYCON_CSR_FULL,
        HYCON_CSR_LOWER,
        HYCON_CSR_UPPER,
        HYCON_PLATE_DISPLACEMENT,
        HYCON_PLATE_FORCE,
        HYCON_CONDENSED_STIFFNESS,
        HYCON_CONDENSED_FLEXIBILITY,
    ]
    .into_iter()
    .collect()
}

// ------------------------------------------------------------------------------------------
// Reading bindgen's output

#[derive(Debug, Clone, PartialEq)]
enum Token {
    Ident(String),
    Number(String),
    Str(String),
    Punct(String),
}

fn tokenize(source: &str) -> Vec<Token> {
    let chars: Vec<char> = source.chars().collect();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c == '/' && chars.get(i + 1) == Some(&'/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && chars.get(i + 1) == Some(&'*') {
            i += 2;
            while i + 1 < chars.len() && !(chars[i] == '*' && chars[i + 1] == '/') {
                i += 1;
            }
            i += 2;
        } else if c.is_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            tokens.push(Token::Ident(chars[start..i].iter().collect()));
        } else if c.is_ascii_digit() {
            let start = i;
            while i < chars.len()
                && (chars[i].is_alphanumeric() || chars[i] == '_' || chars[i] == '.')
            {
                i += 1;
            }
            tokens.push(Token::Number(chars[start..i].iter().collect()));
        } else if c == '"' {
            let mut s = String::new();
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                if chars[i] == '\\' {
                    i += 1;
                }
                s.push(chars[i]);
                i += 1;
            }
            i += 1;
            tokens.push(Token::Str(s));
        } else {
            let two: String = chars[i..(i + 2).min(chars.len())].iter().collect();
            if two == "::" || two == "->" {
                tokens.push(Token::Punct(two));
                i += 2;
            } else {
                tokens.push(Token::Punct(c.to_string()));
                i += 1;
            }
        }
    }
    tokens
}

/// The value of an integer literal as bindgen writes it (`32usize`, `0x10`, `7`).
fn number(text: &str) -> i128 {
    let (body, radix) = match text.strip_prefix("0x") {
        Some(hex) => (hex, 16),
        None => (text, 10),
    };
    let digits: String = body
        .chars()
        .take_while(|c| c.is_digit(radix) || *c == '_')
        .filter(|c| *c != '_')
        .collect();
    i128::from_str_radix(&digits, radix).unwrap_or_else(|e| panic!("number {text}: {e}"))
}

/// Rust's name of a `std::os::raw` / `std::ffi` C type (LP64), or the name unchanged.
fn primitive(name: &str) -> &str {
    match name {
        "c_schar" => "i8",
        "c_uchar" => "u8",
        "c_short" => "i16",
        "c_ushort" => "u16",
        "c_int" => "i32",
        "c_uint" => "u32",
        "c_long" | "c_longlong" => "i64",
        "c_ulong" | "c_ulonglong" => "u64",
        "c_float" => "f32",
        "c_double" => "f64",
        other => other,
    }
}

/// A type in bindgen's output.
#[derive(Debug, Clone, PartialEq)]
enum Ty {
    Named(String),
    Pointer { mutable: bool, to: Box<Ty> },
    Array(Box<Ty>, i128),
    FnPointer { args: Vec<Ty>, ret: Box<Ty> },
    Unit,
}

impl Ty {
    /// The canonical spelling (as `Describe`), type aliases resolved.
    fn canonical(&self, aliases: &BTreeMap<String, Ty>) -> String {
        match self {
            Ty::Named(n) => match aliases.get(n) {
                Some(t) => t.canonical(aliases),
                None => primitive(n).to_string(),
            },
            Ty::Pointer { mutable, to } => {
                let kind = if *mutable { "*mut" } else { "*const" };
                format!("{kind} {}", to.canonical(aliases))
            }
            Ty::Array(t, n) => format!("[{}; {n}]", t.canonical(aliases)),
            Ty::FnPointer { args, ret } => {
                let args: Vec<String> = args.iter().map(|a| a.canonical(aliases)).collect();
                format!(
                    "Option<fn({}) -> {}>",
                    args.join(", "),
                    ret.canonical(aliases)
                )
            }
            Ty::Unit => "()".to_string(),
        }
    }
}

struct Cursor<'a> {
    tokens: &'a [Token],
    at: usize,
}

impl Cursor<'_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.at)
    }
    fn next(&mut self) -> Option<Token> {
        let t = self.tokens.get(self.at).cloned();
        self.at += 1;
        t
    }
    fn is_punct(&self, p: &str) -> bool {
        matches!(self.peek(), Some(Token::Punct(q)) if q == p)
    }
    fn is_ident(&self, i: &str) -> bool {
        matches!(self.peek(), Some(Token::Ident(q)) if q == i)
    }
    fn expect_punct(&mut self, p: &str) {
        match self.next() {
            Some(Token::Punct(q)) if q == p => {}
            t => panic!("expected `{p}`, found {t:?} at token {}", self.at - 1),
        }
    }
    fn ident(&mut self) -> String {
        match self.next() {
            Some(Token::Ident(s)) => s,
            t => panic!(
                "expected an identifier, found {t:?} at token {}",
                self.at - 1
            ),
        }
    }
    /// Skip a balanced group that starts at the current token (`(`, `[` or `{`).
    fn skip_group(&mut self) {
        let mut depth = 0i32;
        loop {
            match self.next() {
                Some(Token::Punct(p)) if p == "(" || p == "[" || p == "{" => depth += 1,
                Some(Token::Punct(p)) if p == ")" || p == "]" || p == "}" => {
                    depth -= 1;
                    if depth == 0 {
                        return;
                    }
                }
                Some(_) => {}
                None => panic!("unbalanced group"),
            }
        }
    }
    /// A path `::a::b::C` or `C`: its last segment.
    fn path(&mut self) -> String {
        if self.is_punct("::") {
            self.next();
        }
        let mut last = self.ident();
        while self.is_punct("::") {
            self.next();
            last = self.ident();
        }
        last
    }
    fn ty(&mut self) -> Ty {
        if self.is_punct("*") {
            self.next();
            let mutable = match self.ident().as_str() {
                "mut" => true,
                "const" => false,
                other => panic!("pointer qualifier {other}"),
            };
            return Ty::Pointer {
                mutable,
                to: Box::new(self.ty()),
            };
        }
        if self.is_punct("[") {
            self.next();
            let t = self.ty();
            self.expect_punct(";");
            let n = match self.next() {
                Some(Token::Number(n)) => number(&n),
                t => panic!("array length {t:?}"),
            };
            self.expect_punct("]");
            return Ty::Array(Box::new(t), n);
        }
        if self.is_punct("(") {
            self.next();
            self.expect_punct(")");
            return Ty::Unit;
        }
        if self.is_ident("unsafe") || self.is_ident("extern") || self.is_ident("fn") {
            if self.is_ident("unsafe") {
                self.next();
            }
            if self.is_ident("extern") {
                self.next();
                if let Some(Token::Str(_)) = self.peek() {
                    self.next();
                }
            }
            assert_eq!(self.ident(), "fn");
            self.expect_punct("(");
            let mut args = Vec::new();
            while !self.is_punct(")") {
                // `name: Type` or `Type`
                if matches!(self.peek(), Some(Token::Ident(_)))
                    && matches!(self.tokens.get(self.at + 1), Some(Token::Punct(p)) if p == ":")
                {
                    self.next();
                    self.next();
                }
                args.push(self.ty());
                if self.is_punct(",") {
                    self.next();
                }
            }
            self.expect_punct(")");
            let ret = if self.is_punct("->") {
                self.next();
                self.ty()
            } else {
                Ty::Unit
            };
            return Ty::FnPointer {
                args,
                ret: Box::new(ret),
            };
        }
        let name = self.path();
        if name == "Option" {
            self.expect_punct("<");
            let inner = self.ty();
            if self.is_punct(",") {
                self.next();
            }
            self.expect_punct(">");
            assert!(
                matches!(inner, Ty::FnPointer { .. }),
                "Option of a non-function type {inner:?}"
            );
            return inner; // a nullable function pointer: canonically `Option<fn(..) -> R>`
        }
        Ty::Named(name)
    }
}

/// What bindgen found in the header.
#[derive(Debug, Default)]
struct Header {
    /// Defined structs, fields in order (name, type).
    structs: BTreeMap<String, Vec<(String, Ty)>>,
    /// Declared-only structs (`_unused: [u8; 0]`).
    opaque: BTreeSet<String>,
    aliases: BTreeMap<String, Ty>,
    constants: BTreeMap<String, i128>,
    /// clang's layout: (size, align) per struct, offset per (struct, field).
    sizes: BTreeMap<String, (i128, i128)>,
    offsets: BTreeMap<(String, String), i128>,
    functions: usize,
}

fn parse_bindings(source: &str) -> Header {
    let tokens = tokenize(source);
    let mut c = Cursor {
        tokens: &tokens,
        at: 0,
    };
    let mut h = Header::default();
    let mut partial_sizes: BTreeMap<String, (Option<i128>, Option<i128>)> = BTreeMap::new();
    while let Some(t) = c.peek().cloned() {
        match t {
            Token::Punct(p) if p == "#" => {
                c.next();
                if c.is_punct("!") {
                    c.next();
                }
                c.skip_group();
            }
            Token::Ident(i) if i == "pub" => {
                c.next();
                match c.ident().as_str() {
                    "struct" => {
                        let name = c.ident();
                        c.expect_punct("{");
                        let mut fields = Vec::new();
                        while !c.is_punct("}") {
                            if c.is_punct("#") {
                                c.next();
                                c.skip_group();
                                continue;
                            }
                            if c.is_ident("pub") {
                                c.next();
                            }
                            let field = c.ident();
                            c.expect_punct(":");
                            let ty = c.ty();
                            fields.push((field, ty));
                            if c.is_punct(",") {
                                c.next();
                            }
                        }
                        c.expect_punct("}");
                        if fields.len() == 1 && fields[0].0 == "_unused" {
                            h.opaque.insert(name);
                        } else {
                            h.structs.insert(name, fields);
                        }
                    }
                    "type" => {
                        let name = c.ident();
                        c.expect_punct("=");
                        let ty = c.ty();
                        c.expect_punct(";");
                        h.aliases.insert(name, ty);
                    }
                    "const" => {
                        let name = c.ident();
                        c.expect_punct(":");
                        let _ty = c.ty();
                        c.expect_punct("=");
                        let negative = c.is_punct("-");
                        if negative {
                            c.next();
                        }
                        let value = match c.next() {
                            Some(Token::Number(n)) => number(&n),
                            t => panic!("constant {name}: value {t:?}"),
                        };
                        c.expect_punct(";");
                        h.constants
                            .insert(name, if negative { -value } else { value });
                    }
                    other => panic!("unexpected item `pub {other}` in the bindings"),
                }
            }
            Token::Ident(i) if i == "unsafe" || i == "extern" => {
                // the function declarations: `unsafe extern "C" { pub fn ...; ... }`
                while !c.is_punct("{") {
                    c.next();
                }
                let start = c.at;
                c.skip_group();
                h.functions += c.tokens[start..c.at]
                    .iter()
                    .filter(|t| matches!(t, Token::Ident(f) if f == "fn"))
                    .count();
            }
            Token::Ident(i) if i == "const" => {
                // clang's layout: `const _: () = { ["Size of X"][... - 32usize]; ... };`
                while !c.is_punct("{") {
                    c.next();
                }
                let start = c.at;
                c.skip_group();
                let body = &c.tokens[start..c.at];
                for (k, t) in body.iter().enumerate() {
                    let Token::Str(what) = t else { continue };
                    // the number is the last literal of the following bracket group
                    let value = body[k + 1..]
                        .iter()
                        .skip_while(|t| **t != Token::Punct("[".into()))
                        .take_while(|t| **t != Token::Punct(";".into()))
                        .filter_map(|t| match t {
                            Token::Number(n) => Some(number(n)),
                            _ => None,
                        })
                        .last()
                        .unwrap_or_else(|| panic!("no number after {what:?}"));
                    if let Some(s) = what.strip_prefix("Size of ") {
                        partial_sizes.entry(s.to_string()).or_default().0 = Some(value);
                    } else if let Some(s) = what.strip_prefix("Alignment of ") {
                        partial_sizes.entry(s.to_string()).or_default().1 = Some(value);
                    } else if let Some(sf) = what.strip_prefix("Offset of field: ") {
                        let (s, f) = sf.split_once("::").expect("Struct::field");
                        h.offsets.insert((s.to_string(), f.to_string()), value);
                    } else {
                        panic!("unknown layout assertion {what:?}");
                    }
                }
                if c.is_punct(";") {
                    c.next();
                }
            }
            Token::Punct(p) if p == ";" => {
                c.next();
            }
            t => panic!("unexpected token {t:?} at {} in the bindings", c.at),
        }
    }
    for (name, (size, align)) in partial_sizes {
        h.sizes.insert(
            name.clone(),
            (
                size.unwrap_or_else(|| panic!("no size for {name}")),
                align.unwrap_or_else(|| panic!("no alignment for {name}")),
            ),
        );
    }
    h
}

fn bindgen_header(header: &Path) -> Header {
    let bindings = bindgen::Builder::default()
        .header(header.to_str().expect("UTF-8 path"))
        .allowlist_item("[Hh]ycon.*|HYCON_.*")
        .layout_tests(true)
        .generate_comments(false)
        .derive_debug(false)
        .derive_copy(false)
        .derive_default(false)
        .formatter(bindgen::Formatter::None)
        .generate()
        .unwrap_or_else(|e| panic!("bindgen on {}: {e}", header.display()));
    parse_bindings(&bindings.to_string())
}

// ------------------------------------------------------------------------------------------
// The system C compiler's view

/// (size, align) per struct, (offset, size) per field, value per constant, as compiled C.
#[derive(Debug, Default)]
struct Compiled {
    sizes: BTreeMap<String, (i128, i128)>,
    fields: BTreeMap<(String, String), (i128, i128)>,
    constants: BTreeMap<String, i128>,
}

fn compile_probe(header: &Path, h: &Header, work: &Path) -> Compiled {
    let mut program = String::from(
        "#include <stdio.h>\n#include <stddef.h>\n#include \"hycon.h\"\nint main(void) {\n",
    );
    for (s, fields) in &h.structs {
        writeln!(
            program,
            "    printf(\"struct {s} %zu %zu\\n\", sizeof(struct {s}), _Alignof(struct {s}));"
        )
        .unwrap();
        for (f, _) in fields {
            writeln!(
                program,
                "    printf(\"field {s} {f} %zu %zu\\n\", offsetof(struct {s}, {f}), \
                 sizeof(((struct {s} *)0)->{f}));"
            )
            .unwrap();
        }
    }
    for k in h.constants.keys() {
        writeln!(
            program,
            "    printf(\"const {k} %lld\\n\", (long long)({k}));"
        )
        .unwrap();
    }
    program.push_str("    return 0;\n}\n");
    std::fs::create_dir_all(work).unwrap();
    // the header under its own name next to the probe, so `#include "hycon.h"` finds this copy
    let include = work.join("include");
    std::fs::create_dir_all(&include).unwrap();
    std::fs::copy(header, include.join("hycon.h")).unwrap();
    let source = work.join("layout_probe.c");
    let exe = work.join("layout_probe");
    std::fs::write(&source, program).unwrap();
    let target = format!(
        "{}-unknown-{}-gnu",
        std::env::consts::ARCH,
        std::env::consts::OS
    );
    let compiler = cc::Build::new()
        .cargo_metadata(false)
        .target(&target)
        .host(&target)
        .opt_level(0)
        .get_compiler();
    let mut cmd = compiler.to_command();
    cmd.args(["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-I"])
        .arg(&include)
        .arg(&source)
        .arg("-o")
        .arg(&exe);
    let status = cmd.status().expect("run the C compiler");
    assert!(
        status.success(),
        "compiling the layout probe failed: {cmd:?}"
    );
    let output = std::process::Command::new(&exe).output().unwrap();
    assert!(output.status.success(), "the layout probe failed");
    let mut c = Compiled::default();
    for line in String::from_utf8(output.stdout).unwrap().lines() {
        let w: Vec<&str> = line.split_whitespace().collect();
        let n = |i: usize| -> i128 { w[i].parse().unwrap() };
        match w[0] {
            "struct" => {
                c.sizes.insert(w[1].to_string(), (n(2), n(3)));
            }
            "field" => {
                c.fields
                    .insert((w[1].to_string(), w[2].to_string()), (n(3), n(4)));
            }
            "const" => {
                c.constants.insert(w[1].to_string(), n(2));
            }
            _ => panic!("probe line {line}"),
        }
    }
    c
}

// ------------------------------------------------------------------------------------------
// The Rust sources: every #[repr(C)] struct, `pub type Hycon*` and `pub const HYCON_*`

fn ffi_source_items() -> (BTreeSet<String>, BTreeSet<String>, BTreeSet<String>) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/ffi");
    let (mut structs, mut aliases, mut constants) = Default::default();
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no sources in {}", dir.display());
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        let mut repr_c = false;
        for line in text.lines().map(str::trim) {
            if line.starts_with("#[repr(C") {
                repr_c = true;
            } else if let Some(rest) = line.strip_prefix("pub struct ") {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if repr_c {
                    let _ = BTreeSet::insert(&mut structs, name);
                }
                repr_c = false;
            } else if let Some(rest) = line.strip_prefix("pub type ") {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if name.starts_with("Hycon") {
                    let _ = BTreeSet::insert(&mut aliases, name);
                }
            } else if let Some(rest) = line.strip_prefix("pub const ") {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if name.starts_with("HYCON_") {
                    let _ = BTreeSet::insert(&mut constants, name);
                }
            } else if !line.starts_with("#[") && !line.starts_with("///") {
                repr_c = false;
            }
        }
    }
    (structs, aliases, constants)
}

// ------------------------------------------------------------------------------------------
// The check

/// Every mismatch between the header at `header` and the Rust definitions (empty: none).
fn layout_errors(header: &Path, work: &Path) -> Vec<String> {
    let h = bindgen_header(header);
    let c = compile_probe(header, &h, work);
    let rust = rust_structs();
    let rust_aliases = rust_aliases();
    let rust_constants = rust_constants();
    let mut errors = Vec::new();
    let mut err = |e: String| errors.push(e);

    // structs: the same set on both sides
    let listed: BTreeSet<&str> = rust.iter().map(|s| s.name).collect();
    for s in h.structs.keys() {
        if !listed.contains(s.as_str()) {
            err(format!(
                "the header defines struct {s}, which tests/layout.rs does not check: add it"
            ));
        }
    }
    let opaque: BTreeSet<String> = OPAQUE.iter().map(|s| s.to_string()).collect();
    if h.opaque != opaque {
        err(format!(
            "opaque types: the header has {:?}, tests/layout.rs expects {:?}",
            h.opaque, opaque
        ));
    }
    for s in &rust {
        let Some(fields) = h.structs.get(s.name) else {
            err(format!("struct {} is not defined in the header", s.name));
            continue;
        };
        let layouts = [
            ("clang", h.sizes.get(s.name).copied()),
            ("C compiler", c.sizes.get(s.name).copied()),
        ];
        for (who, layout) in layouts {
            match layout {
                Some((size, align)) => {
                    if size != s.size as i128 {
                        err(format!(
                            "size of {}: {size} ({who}) != {} (Rust)",
                            s.name, s.size
                        ));
                    }
                    if align != s.align as i128 {
                        err(format!(
                            "alignment of {}: {align} ({who}) != {} (Rust)",
                            s.name, s.align
                        ));
                    }
                }
                None => err(format!("no {who} layout of {}", s.name)),
            }
        }
        let header_names: Vec<&str> = fields.iter().map(|(f, _)| f.as_str()).collect();
        let rust_names: Vec<&str> = s.fields.iter().map(|f| f.name).collect();
        if header_names != rust_names {
            err(format!(
                "fields of {}: {header_names:?} (header) != {rust_names:?} (Rust)",
                s.name
            ));
        }
        for f in &s.fields {
            let key = (s.name.to_string(), f.name.to_string());
            match h.offsets.get(&key) {
                Some(&o) if o == f.offset as i128 => {}
                Some(&o) => err(format!(
                    "offset of {}.{}: {o} (clang) != {} (Rust)",
                    s.name, f.name, f.offset
                )),
                None => err(format!("no clang offset of {}.{}", s.name, f.name)),
            }
            match c.fields.get(&key) {
                Some(&(o, size)) => {
                    if o != f.offset as i128 {
                        err(format!(
                            "offset of {}.{}: {o} (C compiler) != {} (Rust)",
                            s.name, f.name, f.offset
                        ));
                    }
                    if size != f.size as i128 {
                        err(format!(
                            "size of {}.{}: {size} (C compiler) != {} (Rust)",
                            s.name, f.name, f.size
                        ));
                    }
                }
                None => err(format!("no C compiler offset of {}.{}", s.name, f.name)),
            }
            if let Some((_, ty)) = fields.iter().find(|(name, _)| name == f.name) {
                let header_ty = ty.canonical(&h.aliases);
                if header_ty != f.ty {
                    err(format!(
                        "type of {}.{}: {header_ty} (header) != {} (Rust)",
                        s.name, f.name, f.ty
                    ));
                }
            }
        }
    }

    // type aliases (the header's own; others, such as `int32_t`, only resolve types)
    for (name, ty) in h.aliases.iter().filter(|(n, _)| n.starts_with("Hycon")) {
        match rust_aliases.get(name.as_str()) {
            Some(r) if *r == ty.canonical(&h.aliases) => {}
            Some(r) => err(format!(
                "type {name}: {} (header) != {r} (Rust)",
                ty.canonical(&h.aliases)
            )),
            None => err(format!(
                "the header declares type {name}, which tests/layout.rs does not check: add it"
            )),
        }
    }
    for name in rust_aliases.keys() {
        if !h.aliases.contains_key(*name) {
            err(format!("type {name} is not declared in the header"));
        }
    }

    // constants: bindgen's value, the C compiler's value, the Rust value
    for (name, &value) in &h.constants {
        match rust_constants.get(name.as_str()) {
            Some(&r) if r == value => {}
            Some(&r) => err(format!("{name} = {value} (header) != {r} (Rust)")),
            None => err(format!(
                "the header defines {name}, which tests/layout.rs does not check: add it"
            )),
        }
        match c.constants.get(name) {
            Some(&v) if v == value => {}
            v => err(format!("{name} = {v:?} (C compiler) != {value} (bindgen)")),
        }
    }
    for name in rust_constants.keys() {
        if !h.constants.contains_key(*name) {
            err(format!("{name} is not defined in the header"));
        }
    }
    if h.functions == 0 {
        err("bindgen found no functions in the header".into());
    }
    errors
}

fn header_under_test() -> PathBuf {
    match std::env::var_os("HYCON_LAYOUT_HEADER") {
        Some(p) => PathBuf::from(p),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("include/hycon.h"),
    }
}

fn work_dir(name: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("layout-{name}-{}", std::process::id()))
}

#[test]
fn header_layout_matches_rust() {
    let header = header_under_test();
    let work = work_dir("header");
    let errors = layout_errors(&header, &work);
    let _ = std::fs::remove_dir_all(&work);
    assert!(
        errors.is_empty(),
        "{} does not match the Rust definitions:\n  {}",
        header.display(),
        errors.join("\n  ")
    );
}

/// Every `#[repr(C)]` struct, `pub type Hycon*` and `pub const HYCON_*` in `src/ffi/*.rs` is
/// listed in this test (a type added later must be added here).
#[test]
fn every_ffi_item_is_listed() {
    let (structs, aliases, constants) = ffi_source_items();
    let listed: BTreeSet<String> = rust_structs().iter().map(|s| s.name.to_string()).collect();
    assert_eq!(
        structs, listed,
        "#[repr(C)] structs in src/ffi vs tests/layout.rs"
    );
    let listed: BTreeSet<String> = rust_aliases().keys().map(|s| s.to_string()).collect();
    assert_eq!(
        aliases, listed,
        "pub type Hycon* in src/ffi vs tests/layout.rs"
    );
    let listed: BTreeSet<String> = rust_constants().keys().map(|s| s.to_string()).collect();
    assert_eq!(
        constants, listed,
        "pub const HYCON_* in src/ffi vs tests/layout.rs"
    );
}

/// The check catches a mismatch: edited copies of the committed header fail it.
#[test]
fn layout_check_catches_mismatches() {
    let original =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/hycon.h"))
            .unwrap();
    let edits: [(&str, &str, &str, &[&str]); 4] = [
        (
            "field-type",
            "    int32_t slip_sign;",
            "    int64_t slip_sign;",
            &[
                "size of HyconNodeResult: 120 (clang) != 112 (Rust)",
                "size of HyconNodeResult: 120 (C compiler) != 112 (Rust)",
                "offset of HyconNodeResult.tn: 24 (clang) != 16 (Rust)",
                "type of HyconNodeResult.slip_sign: i64 (header) != i32 (Rust)",
            ],
        ),
        (
            "same-size-type",
            "    // when nothing is covered).\n    double normal_gap;",
            "    // when nothing is covered).\n    int64_t normal_gap;",
            &["type of HyconContactNode.normal_gap: i64 (header) != f64 (Rust)"],
        ),
        (
            "constant",
            "#define HYCON_ERROR_CALLBACK -9",
            "#define HYCON_ERROR_CALLBACK -10",
            &["HYCON_ERROR_CALLBACK = -10 (header) != -9 (Rust)"],
        ),
        (
            "unlisted-struct",
            "#ifdef __cplusplus\nextern \"C\" {",
            "typedef struct HyconExtra {\n    double x;\n} HyconExtra;\n\n#ifdef __cplusplus\nextern \"C\" {",
            &["struct HyconExtra, which tests/layout.rs does not check"],
        ),
    ];
    for (name, from, to, expected) in edits {
        assert_eq!(
            original.matches(from).count(),
            1,
            "edit {name}: `{from}` not unique"
        );
        let work = work_dir(name);
        std::fs::create_dir_all(&work).unwrap();
        let copy = work.join("edited.h");
        std::fs::write(&copy, original.replacen(from, to, 1)).unwrap();
        let errors = layout_errors(&copy, &work.join("probe"));
        for e in expected {
            assert!(
                errors.iter().any(|x| x.contains(e)),
                "edit {name}: no error mentions {e:?}; errors: {errors:#?}"
            );
        }
        let _ = std::fs::remove_dir_all(&work);
    }
}
