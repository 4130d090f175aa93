//! Work done in parallel, its output written in order: [`render_in_order`] renders chunks of
//! work (points to evaluate, rows to judge) on every core of rayon's pool and hands each
//! chunk's text to a writer in the chunks' order, so that a long report streams out as it is
//! produced, in bounded memory, and reads the same whatever the number of threads.

use std::collections::BTreeMap;
use std::sync::{Mutex, MutexGuard, PoisonError};

/// Render `chunks` in parallel and `write` their texts in order: chunk `k` is rendered by
/// `render(k, chunk, buffer)` into an empty buffer, on whichever thread of rayon's pool takes
/// it (the threads take the chunks in order, so that with many more chunks than threads the
/// work is shared evenly to the end), and its text is written once chunks `0..k` are.
/// Buffers of written chunks are used again.
///
/// With `stream`, each chunk is written as soon as the chunks before it are (memory: the
/// chunks rendered ahead of the first unwritten one). Without it nothing is written unless
/// every chunk renders: the texts wait for the last chunk (use it when a late chunk can fail
/// and a partial output must not be seen).
///
/// Errors: that of the earliest failing chunk in the chunks' order (chunks after a failed one
/// may be left unrendered). With `stream`, the chunks before it may have been written.
///
/// ```
/// // the squares of 0..1000, ten numbers a chunk, one line each
/// let chunks: Vec<Vec<u64>> = (0..100u64).map(|c| (10 * c..10 * c + 10).collect()).collect();
/// let mut out = String::new();
/// tribez::ordered::render_in_order(
///     chunks,
///     true,
///     |_k, numbers, text| {
///         for n in numbers {
///             text.push_str(&format!("{}\n", n * n));
///         }
///         Ok::<(), String>(())
///     },
///     |text| out.push_str(text),
/// )
/// .unwrap();
/// assert!(out.starts_with("0\n1\n4\n9\n"));
/// assert_eq!(out.lines().count(), 1000);
/// ```
pub fn render_in_order<T, E, R, W>(
    chunks: Vec<T>,
    stream: bool,
    render: R,
    write: W,
) -> Result<(), E>
where
    T: Send,
    E: Send,
    R: Fn(usize, T, &mut String) -> Result<(), E> + Sync,
    W: FnMut(&str) + Send,
{
    let writer = Mutex::new(Writer {
        write,
        stream,
        next: 0,
        ready: BTreeMap::new(),
        spare: Vec::new(),
        failed: None,
    });
    let claims = Mutex::new(chunks.into_iter().enumerate());
    rayon::broadcast(|_| {
        loop {
            let claimed = lock(&claims).next();
            let Some((k, chunk)) = claimed else { break };
            let mut part = {
                let mut w = lock(&writer);
                if w.failed.as_ref().is_some_and(|(j, _)| *j < k) {
                    break;
                }
                w.spare.pop().unwrap_or_default()
            };
            part.clear();
            match render(k, chunk, &mut part) {
                Ok(()) => lock(&writer).put(k, part),
                Err(e) => lock(&writer).fail(k, e),
            }
        }
    });
    let mut w = writer.into_inner().unwrap_or_else(PoisonError::into_inner);
    if let Some((_, e)) = w.failed {
        return Err(e);
    }
    if !stream {
        w.drain();
    }
    debug_assert!(w.ready.is_empty());
    Ok(())
}

/// The writer, shared by the threads that render the chunks.
struct Writer<W, E> {
    write: W,
    /// Whether a chunk is written as soon as the chunks before it are (else at the end).
    stream: bool,
    /// The first chunk not yet written.
    next: usize,
    /// Rendered chunks waiting for the chunks before them.
    ready: BTreeMap<usize, String>,
    /// Buffers of written chunks, to render the next ones into.
    spare: Vec<String>,
    /// The earliest failing chunk so far, and its error.
    failed: Option<(usize, E)>,
}

impl<W: FnMut(&str), E> Writer<W, E> {
    /// Chunk `k` is rendered.
    fn put(&mut self, k: usize, part: String) {
        self.ready.insert(k, part);
        if self.stream {
            self.drain();
        }
    }

    /// Chunk `k` failed with `e` (kept if no earlier chunk failed).
    fn fail(&mut self, k: usize, e: E) {
        if self.failed.as_ref().is_none_or(|(j, _)| k < *j) {
            self.failed = Some((k, e));
        }
    }

    /// Write the chunks that are ready in order from `next`.
    fn drain(&mut self) {
        while let Some(part) = self.ready.remove(&self.next) {
            (self.write)(&part);
            self.next += 1;
            self.spare.push(part);
        }
    }
}

/// `m`'s guard, also after a thread holding it panicked (the panic is reported anyway).
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
mod tests {
    use super::render_in_order;

    #[test]
    fn chunks_are_written_in_order_whatever_thread_renders_them() {
        for stream in [true, false] {
            let mut out = String::new();
            let n = 2000usize;
            render_in_order(
                (0..n).collect(),
                stream,
                |k, i, text| {
                    assert_eq!(k, i);
                    // uneven work, so that chunks finish out of order
                    let spin = (i * 7919) % 300;
                    let mut x = 0u64;
                    for j in 0..spin * 50 {
                        x = x.wrapping_add(j as u64);
                    }
                    std::hint::black_box(x);
                    text.push_str(&format!("{i},"));
                    Ok::<(), ()>(())
                },
                |t| out.push_str(t),
            )
            .unwrap();
            let want: String = (0..n).map(|i| format!("{i},")).collect();
            assert_eq!(out, want);
        }
    }

    #[test]
    fn the_earliest_failing_chunk_is_the_error_and_without_stream_nothing_is_written() {
        let mut out = String::new();
        let r = render_in_order(
            (0..500usize).collect(),
            false,
            |_, i, text| {
                if i % 97 == 13 {
                    return Err(i);
                }
                text.push('x');
                Ok(())
            },
            |t| out.push_str(t),
        );
        assert_eq!(r, Err(13));
        assert!(out.is_empty());
        // streamed: what is written is a prefix of the chunks before the failing one
        let mut out = String::new();
        let r = render_in_order(
            (0..500usize).collect(),
            true,
            |_, i, text| {
                if i == 300 {
                    return Err(i);
                }
                text.push_str(&format!("{i},"));
                Ok(())
            },
            |t| out.push_str(t),
        );
        assert_eq!(r, Err(300));
        let want: String = (0..300).map(|i| format!("{i},")).collect();
        assert!(want.starts_with(&out), "{out}");
    }
}
