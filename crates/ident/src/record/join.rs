//! A record whose input and output were logged to two files (a common logger layout: the
//! spray dryer's `…StepDataIn.txt` and `…StepDataOut.txt`, each a time and a value on its
//! own grid), joined on time. Each output sample takes the input's last value logged at or
//! before its instant: the input is held between its samples, as a command or a setpoint
//! is, and a step logged as two rows at one instant (its vertical edge) takes the later
//! row. Output samples before the input's first instant take its first value (the input
//! at its first level), and a note counts them.

use crate::record::data::{DataError, DataNote, StepTest};

/// `output` (a record whose own input, if any, is replaced) with the input of `input` (a
/// record whose output column holds the input's values), joined on `output`'s instants.
pub fn join_on_time(mut output: StepTest, input: &StepTest) -> Result<StepTest, DataError> {
    let (Some(&first), Some(&end)) = (input.time.first(), output.time.last()) else {
        return Err(DataError::Empty);
    };
    if first > end {
        return Err(DataError::InputAfterOutput {
            input_start: first,
            output_end: end,
        });
    }
    let held: Vec<f64> = output
        .time
        .iter()
        .map(|&t| {
            let logged = input.time.partition_point(|&s| s <= t);
            input.output[logged.saturating_sub(1)]
        })
        .collect();
    let held_back = output.time.partition_point(|&t| t < first);
    output.input = Some(held);
    output.input_name = Some(input.output_name.clone());
    output.notes.push(DataNote::InputJoined { held_back });
    Ok(output)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(time: &[f64], values: &[f64]) -> StepTest {
        StepTest {
            time: time.to_vec(),
            output: values.to_vec(),
            input: None,
            time_name: "t".into(),
            output_name: "v".into(),
            input_name: None,
            sampling_period: None,
            notes: Vec::new(),
        }
    }

    #[test]
    fn each_sample_takes_the_last_input_logged_at_or_before_it() {
        let out = record(&[0.3, 0.7, 1.0, 1.4, 2.0], &[5.0; 5]);
        // A step logged as two rows at t = 1.0 (its vertical edge).
        let input = record(&[0.5, 1.0, 1.0, 1.8], &[0.0, 0.0, 10.0, 10.0]);
        let joined = join_on_time(out, &input).unwrap();
        assert_eq!(joined.input, Some(vec![0.0, 0.0, 10.0, 10.0, 10.0]));
        assert_eq!(joined.notes, vec![DataNote::InputJoined { held_back: 1 }]);
    }

    #[test]
    fn files_that_share_no_time_are_refused() {
        let out = record(&[0.0, 1.0], &[1.0, 2.0]);
        let input = record(&[5.0, 6.0], &[0.0, 1.0]);
        assert_eq!(
            join_on_time(out, &input),
            Err(DataError::InputAfterOutput {
                input_start: 5.0,
                output_end: 1.0
            })
        );
    }
}
