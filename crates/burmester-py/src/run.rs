//! Long computations from Python: the GIL released, Ctrl-C and progress.
//!
//! The work runs on a worker thread (which uses rayon inside) with a core
//! [`Control`]; the calling thread, which Python's signal handlers run on,
//! waits for it and every [`POLL`] re-enters Python to run the signal
//! handlers (`PyErr_CheckSignals`) and the caller's progress callback. A
//! pending `KeyboardInterrupt` (or an exception from the callback) sets the
//! cancel flag; the worker stops at its next row and the call
//! raises, its message saying how much of an `out=` array was written.

use core::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use burmester::Control;
use pyo3::exceptions::PyKeyboardInterrupt;
use pyo3::prelude::*;

use crate::errors::IntoPy;

/// How often the waiting thread runs the signal handlers and the progress
/// callback.
pub(crate) const POLL: Duration = Duration::from_millis(25);

/// Below this many samples a computation runs without a watcher (it ends
/// in well under [`POLL`]), unless a progress callback is given.
pub(crate) const WATCH_MIN_SAMPLES: usize = 1 << 18;

/// Runs `work` with the GIL released. When `watch` (or a `progress`
/// callback is given), the calling thread watches for Ctrl-C and calls
/// `progress(done, total)` while it runs. `partial` names what a cancelled
/// run leaves half-written (for the message), if anything.
pub(crate) fn run<T: Send>(
    py: Python<'_>,
    watch: bool,
    progress: Option<&Bound<'_, PyAny>>,
    partial: Option<&str>,
    work: impl FnOnce(&Control<'_>) -> burmester::Result<T> + Send,
) -> PyResult<T> {
    run_in(py, watch, progress, partial, "rows", work)
}

/// [`run`] of work whose progress counts `unit` (`"rows"`, `"samples"`,
/// `"driving rows over all driven centers"`), the word the interrupt
/// message uses.
pub(crate) fn run_in<T: Send>(
    py: Python<'_>,
    watch: bool,
    progress: Option<&Bound<'_, PyAny>>,
    partial: Option<&str>,
    unit: &str,
    work: impl FnOnce(&Control<'_>) -> burmester::Result<T> + Send,
) -> PyResult<T> {
    if !watch && progress.is_none() {
        return py.detach(|| work(&Control::new())).py();
    }
    let cancel = AtomicBool::new(false);
    let done = AtomicUsize::new(0);
    let total = AtomicUsize::new(0);
    let progress = progress.map(|p| p.clone().unbind());
    let mut raised: Option<PyErr> = None;
    let result = py.detach(|| {
        // The work runs as a job of rayon's pool (whose threads it uses
        // anyway): no thread is started per call. This thread waits in the
        // scope's body, then for the job at the scope's end.
        let mut out = None;
        let finished = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            rayon::in_place_scope(|s| {
                let (tx, rx) = mpsc::channel::<()>();
                let (cancel, done, total) = (&cancel, &done, &total);
                let out = &mut out;
                s.spawn(move |_| {
                    let hook = |d: usize, t: usize| {
                        done.store(d, Ordering::Relaxed);
                        total.store(t, Ordering::Relaxed);
                    };
                    let control = Control::new().with_cancel(cancel).with_progress(&hook);
                    *out = Some(work(&control));
                    // The watcher may have stopped listening; nothing to do then.
                    let _ = tx.send(());
                });
                loop {
                    match rx.recv_timeout(POLL) {
                        Ok(()) | Err(mpsc::RecvTimeoutError::Disconnected) => break,
                        Err(mpsc::RecvTimeoutError::Timeout) => {}
                    }
                    if raised.is_some() {
                        continue;
                    }
                    let r = Python::attach(|py| -> PyResult<()> {
                        py.check_signals()?;
                        if let Some(cb) = &progress {
                            let t = total.load(Ordering::Relaxed);
                            if t > 0 {
                                cb.call1(py, (done.load(Ordering::Relaxed), t))?;
                            }
                        }
                        Ok(())
                    });
                    if let Err(e) = r {
                        cancel.store(true, Ordering::Relaxed);
                        raised = Some(e);
                    }
                }
            })
        }));
        finished.map(|()| out)
    });
    let result = match result {
        Ok(Some(r)) => r,
        Ok(None) => unreachable!("the scope ends after its job"),
        Err(panic) => std::panic::resume_unwind(panic),
    };
    if let Some(e) = raised {
        if result.is_ok() {
            // It finished before it saw the flag: the result is whole, but
            // the caller asked to stop; honour the interrupt.
            return Err(e);
        }
        if e.is_instance_of::<PyKeyboardInterrupt>(py) {
            let (d, t) = (done.load(Ordering::Relaxed), total.load(Ordering::Relaxed));
            let msg = match partial {
                Some(what) => format!(
                    "interrupted after {d} of {t} {unit}; {what} holds a partial result (the rows \
                     not reached keep their old values)"
                ),
                None if t == 0 => "interrupted".to_owned(),
                None => format!("interrupted after {d} of {t} {unit}"),
            };
            return Err(PyKeyboardInterrupt::new_err(msg));
        }
        return Err(e);
    }
    if let Some(cb) = &progress {
        let t = total.load(Ordering::Relaxed);
        if t > 0 {
            cb.call1(py, (t, t))?;
        }
    }
    result.py()
}

/// Items converted to Python objects between two runs of the signal
/// handlers in [`list_polled`].
const LIST_POLL: usize = 4096;

/// A Python list of `items`, each made by `make`, running the signal
/// handlers every few thousand items: a list of millions of objects takes
/// seconds to build, and Ctrl-C stops it (`KeyboardInterrupt`). The list
/// grows by Python's allocator, so a failed allocation is a
/// `MemoryError`.
pub(crate) fn list_polled<'py, T>(
    py: Python<'py>,
    items: impl IntoIterator<Item = T>,
    mut make: impl FnMut(T) -> PyResult<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, pyo3::types::PyList>> {
    use pyo3::types::{PyList, PyListMethods};
    let list = PyList::empty(py);
    for (n, item) in items.into_iter().enumerate() {
        if n % LIST_POLL == LIST_POLL - 1 {
            py.check_signals()?;
        }
        list.append(make(item)?)?;
    }
    Ok(list)
}
