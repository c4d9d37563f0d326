//! Independent work on all cores (with the `parallel` feature), its output in the input's
//! order: the axis never depends on the threads' timing.

/// `f` of each of `items`, in their order (in parallel where the feature is on).
pub(crate) fn in_order<T: Sync, U: Send>(items: &[T], f: impl Fn(&T) -> U + Sync + Send) -> Vec<U> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        items.par_iter().map(f).collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        items.iter().map(f).collect()
    }
}
