//! Long work off the UI thread: a job runs on its own thread, sends progress messages, can
//! be cancelled, and hands back its result. The session that owns it polls it once per frame;
//! the job wakes the UI through a [`Waker`] (no egui type here), so a frame follows each
//! message.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, Sender, TryRecvError, channel};

/// What wakes the UI when a job has news (the top level hands one in; tests need none).
pub type Waker = Arc<dyn Fn() + Send + Sync>;

/// What a running job reports.
pub enum Message<P, R> {
    Progress(P),
    Done(R),
}

/// A handle to a running job.
pub struct Job<P, R> {
    cancel: Arc<AtomicBool>,
    messages: Receiver<Message<P, R>>,
    /// The latest progress received.
    pub progress: Option<P>,
}

/// What the job's closure gets: a way to report and to learn it was cancelled.
#[derive(Clone)]
pub struct Context<P, R> {
    cancel: Arc<AtomicBool>,
    sender: Sender<Message<P, R>>,
    waker: Option<Waker>,
}

impl<P, R> Context<P, R> {
    /// Sends progress (ignored if the UI is gone) and asks for a repaint.
    pub fn report(&self, progress: P) {
        let _ = self.sender.send(Message::Progress(progress));
        self.wake();
    }

    pub fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    fn wake(&self) {
        if let Some(wake) = &self.waker {
            wake();
        }
    }
}

impl<P: Send + 'static, R: Send + 'static> Job<P, R> {
    /// Starts `work` on a new thread; `waker` wakes the UI when messages arrive.
    pub fn spawn(
        waker: Option<Waker>,
        work: impl FnOnce(&Context<P, R>) -> R + Send + 'static,
    ) -> Self {
        let cancel = Arc::new(AtomicBool::new(false));
        let (sender, messages) = channel();
        let context = Context {
            cancel: cancel.clone(),
            sender,
            waker,
        };
        std::thread::spawn(move || {
            let result = work(&context);
            let _ = context.sender.send(Message::Done(result));
            context.wake();
        });
        Self {
            cancel,
            messages,
            progress: None,
        }
    }

    /// Asks the job to stop at its next check.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Takes the messages that arrived; returns the result once the job is done.
    pub fn poll(&mut self) -> Option<R> {
        loop {
            match self.messages.try_recv() {
                Ok(Message::Progress(p)) => self.progress = Some(p),
                Ok(Message::Done(r)) => return Some(r),
                Err(TryRecvError::Empty) => return None,
                Err(TryRecvError::Disconnected) => return None,
            }
        }
    }

    /// Waits for the result (tests and the command line).
    pub fn wait(mut self) -> Option<R> {
        loop {
            match self.messages.recv() {
                Ok(Message::Progress(p)) => self.progress = Some(p),
                Ok(Message::Done(r)) => return Some(r),
                Err(_) => return None,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_progress_and_result() {
        let job: Job<u32, &str> = Job::spawn(None, |ctx| {
            for k in 0..3 {
                ctx.report(k);
            }
            "done"
        });
        assert_eq!(job.wait(), Some("done"));
    }

    #[test]
    fn the_waker_is_called_for_progress_and_result() {
        let calls = Arc::new(std::sync::atomic::AtomicUsize::new(0));
        let counted = calls.clone();
        let waker: Waker = Arc::new(move || {
            counted.fetch_add(1, Ordering::SeqCst);
        });
        let job: Job<u32, u32> = Job::spawn(Some(waker), |ctx| {
            ctx.report(1);
            ctx.report(2);
            3
        });
        assert_eq!(job.wait(), Some(3));
        // Both progress messages woke the UI before the result was sent (the result's own
        // call may still be on its way).
        assert!(calls.load(Ordering::SeqCst) >= 2);
    }

    #[test]
    fn cancel_reaches_the_work() {
        let (started_tx, started_rx) = channel();
        let mut job: Job<(), bool> = Job::spawn(None, move |ctx| {
            let _ = started_tx.send(());
            while !ctx.cancelled() {
                std::thread::yield_now();
            }
            true
        });
        started_rx.recv().unwrap();
        job.cancel();
        let result = loop {
            if let Some(r) = job.poll() {
                break r;
            }
            std::thread::yield_now();
        };
        assert!(result);
    }
}
