//! How a side's faces connect: the check that they form one surface ([`check_surface`]), and
//! the connected pieces of a set of items ([`Pieces`]), which that check and the model's bodies
//! (bricks joined by shared nodes: `FacePair::check_on`) are built on.

use crate::error::{Error, Result};
use std::collections::BTreeMap;

/// The connected pieces of items `0..n`, joined pair by pair (union by smaller root, path
/// halving).
#[derive(Debug, Clone)]
pub struct Pieces {
    parent: Vec<usize>,
}

impl Pieces {
    /// `n` items, each a piece of its own.
    pub fn new(n: usize) -> Self {
        Pieces {
            parent: (0..n).collect(),
        }
    }

    /// The piece of item `i`: its smallest item, once every join is made. Panics if `i >= n`.
    pub fn root(&mut self, mut i: usize) -> usize {
        while self.parent[i] != i {
            self.parent[i] = self.parent[self.parent[i]];
            i = self.parent[i];
        }
        i
    }

    /// Put items `i` and `j` in one piece.
    pub fn join(&mut self, i: usize, j: usize) {
        let (ri, rj) = (self.root(i), self.root(j));
        self.parent[ri.max(rj)] = ri.min(rj);
    }

    /// The number of pieces.
    pub fn count(&mut self) -> usize {
        (0..self.parent.len())
            .filter(|&i| self.root(i) == i)
            .count()
    }
}

/// The edges of a face as node-id pairs, smaller first.
pub fn edges(f: &[usize; 4]) -> impl Iterator<Item = (usize, usize)> + '_ {
    (0..4).map(|i| {
        let (p, q) = (f[i], f[(i + 1) % 4]);
        (p.min(q), p.max(q))
    })
}

/// `faces`, one side of a pair (node ids, any positions), form one surface: no edge is an edge
/// of more than two of them, and they are connected through shared edges (a corner shared
/// alone does not join two faces). One side of one body is one surface: its frames take one
/// reference direction and its edge is where its contact ends.
///
/// # Errors
/// [`Error::InvalidInput`] naming the side and an edge of three faces, or the number of pieces
/// and a face of a piece other than face 0's.
pub fn check_surface(side: &str, faces: &[[usize; 4]]) -> Result<()> {
    let mut on_edge: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
    for (i, f) in faces.iter().enumerate() {
        for e in edges(f) {
            on_edge.entry(e).or_default().push(i);
        }
    }
    let mut pieces = Pieces::new(faces.len());
    for ((p, q), on) in &on_edge {
        match on.as_slice() {
            [i, j] => pieces.join(*i, *j),
            [_] => {}
            _ => {
                return Err(Error::InvalidInput(format!(
                    "contact side {side} is not a surface: its edge ({p}, {q}) is an edge of {} \
                     of its faces ({on:?}), a surface's of two at most",
                    on.len()
                )));
            }
        }
    }
    if let Some(i) = (1..faces.len()).find(|&i| pieces.root(i) != 0) {
        return Err(Error::InvalidInput(format!(
            "contact side {side} is not one connected surface: its {} faces form {} pieces \
             that share no edge (face 0 and face {i} are in different pieces); give each \
             piece a pair of its own",
            faces.len(),
            pieces.count()
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The faces of an `n x m` grid of nodes `i + n j`.
    fn grid(n: usize, m: usize) -> Vec<[usize; 4]> {
        let id = |i: usize, j: usize| i + n * j;
        (0..m - 1)
            .flat_map(|j| {
                (0..n - 1).map(move |i| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
            })
            .collect()
    }

    #[test]
    fn pieces_join_and_count() {
        let mut p = Pieces::new(5);
        p.join(3, 1);
        p.join(4, 3);
        assert_eq!((p.root(4), p.root(2), p.count()), (1, 2, 3));
    }

    #[test]
    fn a_grid_is_one_surface_and_its_pieces_are_named() {
        let faces = grid(4, 3);
        check_surface("A", &faces).unwrap();
        // faces 0 and 2 of the first row touch face 1 only; without it, they share no edge
        let apart = vec![faces[0], faces[2]];
        let err = check_surface("A", &apart).unwrap_err().to_string();
        assert!(err.contains("2 pieces") && err.contains("face 1"), "{err}");
        // two faces sharing a corner alone
        let corner = vec![faces[0], faces[4]];
        let err = check_surface("B", &corner).unwrap_err().to_string();
        assert!(err.contains("contact side B is not one connected"), "{err}");
        // a third face on an edge
        let mut three = faces.clone();
        three.push([1, 5, 20, 21]);
        let err = check_surface("A", &three).unwrap_err().to_string();
        assert!(err.contains("edge (1, 5) is an edge of 3"), "{err}");
    }
}
