//! Structured mutations of a valid text file, as proptest strategies: a
//! line dropped, duplicated or swapped with another; a cell (a CSV field, a
//! TOML value, an array element) replaced by garbage, NaN, a huge or tiny
//! number or nothing; the file cut at a byte; bytes (non-UTF-8 too)
//! inserted; or the whole file replaced by random bytes. Indices are taken
//! modulo the lines and cells the file has when the mutation is applied.

use proptest::prelude::*;

/// One mutation.
#[derive(Debug, Clone)]
pub enum Mutation {
    DropLine(usize),
    DuplicateLine(usize),
    SwapLines(usize, usize),
    ReplaceCell {
        line: usize,
        cell: usize,
        with: Vec<u8>,
    },
    Truncate(usize),
    Insert {
        at: usize,
        bytes: Vec<u8>,
    },
    Random(Vec<u8>),
}

/// Replacement cells that readers get wrong most often.
const NASTY: &[&str] = &[
    "NaN",
    "nan",
    "inf",
    "-inf",
    "+inf",
    "1e308",
    "-1e308",
    "1e999",
    "1e-300",
    "5e-324",
    "-0",
    "0",
    "-1",
    "",
    " ",
    "abc",
    "\"x\"",
    "\"\"",
    "[]",
    "{}",
    "[1e308, -1e308]",
    "99999999999999999999",
    "18446744073709551616",
    "-9223372036854775809",
    "true",
    "0x10",
    "1_000",
    "１",
    "\u{feff}",
    "\"",
    "'",
    "=",
    "[vehicle]",
    "#",
    "$",
    "1,2",
    "\r",
];

fn cell() -> impl Strategy<Value = Vec<u8>> {
    prop_oneof![
        3 => prop::sample::select(NASTY).prop_map(|s| s.as_bytes().to_vec()),
        1 => prop::collection::vec(any::<u8>(), 0..6),
        1 => (-1e6f64..1e6).prop_map(|v| format!("{v}").into_bytes()),
    ]
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let idx = || 0usize..100_000;
    prop_oneof![
        2 => idx().prop_map(Mutation::DropLine),
        2 => idx().prop_map(Mutation::DuplicateLine),
        2 => (idx(), idx()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        6 => (idx(), 0usize..16, cell()).prop_map(|(line, cell, with)| Mutation::ReplaceCell { line, cell, with }),
        2 => idx().prop_map(Mutation::Truncate),
        2 => (idx(), prop::collection::vec(any::<u8>(), 1..4)).prop_map(|(at, bytes)| Mutation::Insert { at, bytes }),
        1 => prop::collection::vec(any::<u8>(), 0..64).prop_map(Mutation::Random),
    ]
}

/// One to three mutations.
pub fn mutations() -> impl Strategy<Value = Vec<Mutation>> {
    prop::collection::vec(mutation(), 1..4)
}

/// Lines with their terminators.
fn lines(b: &[u8]) -> Vec<Vec<u8>> {
    b.split_inclusive(|&c| c == b'\n')
        .map(<[u8]>::to_vec)
        .collect()
}

/// Is `c` a separator between cells (CSV, TOML values, arrays, tables)?
fn separator(c: u8) -> bool {
    matches!(c, b',' | b'=' | b'[' | b']' | b'{' | b'}' | b'\n')
}

/// Replaces the `k`-th cell (modulo their number) of `line`.
fn replace_cell(line: &[u8], k: usize, with: &[u8]) -> Vec<u8> {
    let mut cuts = vec![0];
    cuts.extend(
        line.iter()
            .enumerate()
            .filter(|(_, &c)| separator(c))
            .map(|(i, _)| i + 1),
    );
    let k = k % cuts.len();
    let start = cuts[k];
    let end = line[start..]
        .iter()
        .position(|&c| separator(c))
        .map_or(line.len(), |p| start + p);
    [&line[..start], with, &line[end..]].concat()
}

/// `base` with `m` applied.
pub fn apply(base: &[u8], ms: &[Mutation]) -> Vec<u8> {
    let mut out = base.to_vec();
    for m in ms {
        let mut ls = lines(&out);
        let n = ls.len().max(1);
        match m {
            Mutation::DropLine(i) if !ls.is_empty() => {
                ls.remove(i % n);
            }
            Mutation::DuplicateLine(i) if !ls.is_empty() => {
                let l = ls[i % n].clone();
                ls.insert(i % n, l);
            }
            Mutation::SwapLines(a, b) if !ls.is_empty() => ls.swap(a % n, b % n),
            Mutation::ReplaceCell { line, cell, with } if !ls.is_empty() => {
                ls[line % n] = replace_cell(&ls[line % n], *cell, with);
            }
            Mutation::Truncate(at) => {
                out.truncate(at % (out.len() + 1));
                continue;
            }
            Mutation::Insert { at, bytes } => {
                let at = at % (out.len() + 1);
                out.splice(at..at, bytes.iter().copied());
                continue;
            }
            Mutation::Random(bytes) => {
                out = bytes.clone();
                continue;
            }
            _ => {}
        }
        out = ls.concat();
    }
    out
}

#[test]
fn mutations_do_what_they_say() {
    let base = b"t,speed\n0,1\n2,3\n";
    let cell = |line, cell, with: &str| Mutation::ReplaceCell {
        line,
        cell,
        with: with.as_bytes().to_vec(),
    };
    assert_eq!(apply(base, &[Mutation::DropLine(4)]), b"t,speed\n2,3\n");
    assert_eq!(
        apply(base, &[Mutation::DuplicateLine(2)]),
        b"t,speed\n0,1\n2,3\n2,3\n"
    );
    assert_eq!(
        apply(base, &[Mutation::SwapLines(0, 2)]),
        b"2,3\n0,1\nt,speed\n"
    );
    assert_eq!(apply(base, &[cell(1, 1, "NaN")]), b"t,speed\n0,NaN\n2,3\n");
    assert_eq!(apply(base, &[cell(2, 0, "")]), b"t,speed\n0,1\n,3\n");
    assert_eq!(apply(b"a = [1, 2]\n", &[cell(0, 2, "x")]), b"a = [x, 2]\n");
    assert_eq!(apply(base, &[Mutation::Truncate(10)]), b"t,speed\n0,");
}
