//! A progress line for long commands: a command that runs over a second shows, on a
//! terminal, what it is doing (the library's stage and its count of units) on stderr, and
//! clears it when done; off a terminal, or under a second, nothing is written.

use curve::watch::Watch;
use std::io::{IsTerminal, Write};
use std::sync::mpsc;
use std::sync::Arc;
use std::time::Duration;

/// How long a command runs before its progress is shown.
const QUIET_FOR: Duration = Duration::from_secs(1);

/// How often the line is written again.
const EVERY: Duration = Duration::from_millis(250);

/// Runs `work` under a watch whose progress a second thread writes to stderr (a terminal)
/// from [`QUIET_FOR`] on.
pub(crate) fn watched<T>(work: impl FnOnce() -> T) -> T {
    let watch = Arc::new(Watch::default());
    if !std::io::stderr().is_terminal() {
        return watch.run(work);
    }
    let (done, finished) = mpsc::channel::<()>();
    let shown = Arc::clone(&watch);
    let writer = std::thread::spawn(move || {
        if finished.recv_timeout(QUIET_FOR) != Err(mpsc::RecvTimeoutError::Timeout) {
            return;
        }
        let mut err = std::io::stderr();
        loop {
            let p = shown.progress();
            if !p.stage.is_empty() {
                let _ = write!(err, "\r\x1b[Kcurvekit: {}: {}", p.stage, p.done);
                let _ = err.flush();
            }
            if finished.recv_timeout(EVERY) != Err(mpsc::RecvTimeoutError::Timeout) {
                let _ = write!(err, "\r\x1b[K");
                let _ = err.flush();
                return;
            }
        }
    });
    let out = watch.run(work);
    drop(done);
    let _ = writer.join();
    out
}
