//! The progress and cancellation of a long computation, between the thread that does it and
//! one that watches (a terminal's progress line, Python's check for Ctrl-C).
//!
//! The watcher makes a [`Watch`] and runs the work under it ([`Watch::run`]); each of the
//! library's long loops starts a [`stage`] and, at every unit of work, counts it and asks
//! whether to go on ([`Stage::go_on`]): it stops early where the watch is cancelled (its
//! caller then answers "cancelled", never a partial result). Work run under no watch is never
//! cancelled and counts nothing.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// What a watched computation is doing: the stage and the units of work done in it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// The stage (empty before the first).
    pub stage: &'static str,
    /// Units of work done in it (pairs of pieces, edges, …).
    pub done: usize,
}

/// A long computation's cancellation flag and progress, shared with its watcher.
///
/// ```
/// use curve::watch::{self, Watch};
/// use std::sync::Arc;
/// let w = Arc::new(Watch::default());
/// w.run(|| {
///     let stage = watch::stage("counting");
///     assert!(stage.go_on(3));
/// });
/// assert_eq!(w.progress(), watch::Progress { stage: "counting", done: 3 });
/// w.cancel();
/// assert!(w.run(watch::cancelled));
/// assert!(!w.run(|| watch::stage("more").go_on(1)));
/// assert!(!watch::cancelled()); // (outside the run: no watch)
/// ```
#[derive(Debug, Default)]
pub struct Watch {
    cancelled: AtomicBool,
    stage: Mutex<&'static str>,
    done: AtomicUsize,
}

thread_local! {
    static CURRENT: RefCell<Option<Arc<Watch>>> = const { RefCell::new(None) };
}

impl Watch {
    /// Asks the work to stop: its loops see it at their next unit.
    pub fn cancel(&self) {
        self.cancelled.store(true, Ordering::Relaxed);
    }

    /// Whether the work was asked to stop.
    pub fn is_cancelled(&self) -> bool {
        self.cancelled.load(Ordering::Relaxed)
    }

    /// Counts `n` more units of work done in the stage.
    pub fn advance(&self, n: usize) {
        self.done.fetch_add(n, Ordering::Relaxed);
    }

    /// The stage and the units done in it.
    pub fn progress(&self) -> Progress {
        Progress {
            stage: *self.stage.lock().unwrap_or_else(|e| e.into_inner()),
            done: self.done.load(Ordering::Relaxed),
        }
    }

    /// Runs `work` on this thread under this watch (the watch it ran under before is back
    /// after it).
    pub fn run<T>(self: &Arc<Self>, work: impl FnOnce() -> T) -> T {
        let before = CURRENT.with(|c| c.replace(Some(Arc::clone(self))));
        // (Put back on the way out, a panic's way too.)
        struct Restore(Option<Arc<Watch>>);
        impl Drop for Restore {
            fn drop(&mut self) {
                let before = self.0.take();
                CURRENT.with(|c| *c.borrow_mut() = before);
            }
        }
        let _restore = Restore(before);
        work()
    }
}

/// Whether the work on this thread was asked to stop.
pub fn cancelled() -> bool {
    CURRENT.with(|c| c.borrow().as_ref().is_some_and(|w| w.is_cancelled()))
}

/// Starts a stage of the work on this thread (its count of units from nothing), under the
/// watch the thread runs under, if any.
pub fn stage(name: &'static str) -> Stage {
    let watch = CURRENT.with(|c| c.borrow().clone());
    if let Some(w) = &watch {
        *w.stage.lock().unwrap_or_else(|e| e.into_inner()) = name;
        w.done.store(0, Ordering::Relaxed);
    }
    Stage { watch }
}

/// A stage of watched work, for its loop (shared by the threads it hands the work to).
#[derive(Debug, Clone)]
pub struct Stage {
    watch: Option<Arc<Watch>>,
}

impl Stage {
    /// Whether the stage runs under a watch (work that cannot look at the watch itself, a
    /// foreign library's, may then be run where it can be left when cancelled).
    pub fn is_watched(&self) -> bool {
        self.watch.is_some()
    }

    /// Whether the watch was asked to stop (never under no watch): for a loop whose units
    /// cost more to look at than this does.
    pub fn cancelled(&self) -> bool {
        self.watch.as_ref().is_some_and(|w| w.is_cancelled())
    }

    /// Counts `units` more units of work done and answers whether to go on: false once the
    /// watch is cancelled (never under no watch).
    pub fn go_on(&self, units: usize) -> bool {
        match &self.watch {
            Some(w) => {
                w.advance(units);
                !w.is_cancelled()
            }
            None => true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cancel_from_another_thread_is_seen_and_the_watch_ends_with_the_run() {
        let w = Arc::new(Watch::default());
        let seen = w.run(|| {
            let other = Arc::clone(&w);
            std::thread::spawn(move || other.cancel()).join().unwrap();
            cancelled()
        });
        assert!(seen);
        assert!(!cancelled() && stage("after").go_on(1));
        let nested = Arc::new(Watch::default());
        w.run(|| {
            nested.run(|| assert!(!cancelled()));
            assert!(cancelled());
        });
    }
}
