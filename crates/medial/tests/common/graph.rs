//! The medial axis as a graph: its connected components and independent cycles (union-find
//! over its edges), to compare with the region's one piece per part and one cycle per hole.
#![allow(dead_code, unreachable_pub)]

use medial::MedialAxis;

/// The number of connected components of the axis's graph and of its independent cycles
/// (edges + components − nodes).
pub fn components_and_cycles(a: &MedialAxis) -> (usize, usize) {
    let n = a.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn root(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            i = p[i];
        }
        i
    }
    for e in &a.edges {
        let (x, y) = (root(&mut parent, e.from), root(&mut parent, e.to));
        parent[x] = y;
    }
    let components = (0..n).filter(|&i| root(&mut parent, i) == i).count();
    (components, a.edges.len() + components - n)
}
