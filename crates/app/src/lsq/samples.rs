//! The sampled record the least-squares mode works on ([`Samples`]): time, input and output
//! at each sample the Identify mode's fit sees, with its sampling period. A plain fact with
//! no egui in it, below the session that holds it and the RLS animation that runs on it.

use degrau_ident::fit::FitData;
use degrau_ident::lsq::arx;
use degrau_ident::record::data::StepTest;

/// The sampled record: time (s), input and output at each sample.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Samples {
    pub time: Vec<f64>,
    pub u: Vec<f64>,
    pub y: Vec<f64>,
}

impl Samples {
    /// The samples a fit sees (window and filter applied), with the input column's own
    /// samples over them when the record has one (two rows at one time, the state before a
    /// step and the step, stay two rows); otherwise the input as the model sees it (u0 plus
    /// its deviation, held between samples: a typed step) at each sample time.
    pub fn of(test: &StepTest, data: &FitData) -> Self {
        let n = data.times.len();
        let measured = test.input.as_ref().and_then(|u| {
            let first = test
                .time
                .iter()
                .position(|&t| Some(&t) == data.times.first())?;
            let rows = first..first + n;
            let same = test.time.get(rows.clone())? == data.times.as_slice();
            u.get(rows).filter(|_| same).map(<[f64]>::to_vec)
        });
        Self {
            u: measured.unwrap_or_else(|| {
                data.times
                    .iter()
                    .map(|&t| data.input.u0 + data.input.deviation_at(t))
                    .collect()
            }),
            time: data.times.clone(),
            y: data.y.clone(),
        }
    }

    /// The sampling period h (s): the median interval.
    pub fn ts(&self) -> f64 {
        arx::sampling_period(&self.time)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_input_is_sampled_as_the_model_sees_it() {
        let time: Vec<f64> = (0..6).map(f64::from).collect();
        let u = [20.0, 20.0, 35.0, 35.0, 35.0, 35.0];
        let input = degrau_ident::model::excitation::Excitation::measured(
            &time,
            &u,
            None,
            degrau_ident::model::excitation::Hold::Zoh,
        )
        .unwrap();
        let data = FitData {
            times: time.clone(),
            y: vec![1.0; 6],
            input,
        };
        let test = StepTest {
            time: time.clone(),
            output: data.y.clone(),
            input: None,
            time_name: "t".into(),
            output_name: "y".into(),
            input_name: None,
            sampling_period: None,
            notes: Vec::new(),
        };
        assert_eq!(Samples::of(&test, &data).u, u);
        // With the input column, its own samples (a window from the second sample on).
        let mut column = u.to_vec();
        column[0] = 19.0;
        let test = StepTest {
            input: Some(column),
            ..test
        };
        let window = FitData {
            times: time[1..].to_vec(),
            y: vec![1.0; 5],
            input: data.input.clone(),
        };
        assert_eq!(Samples::of(&test, &window).u, u[1..]);
    }
}
