//! A system as code for the course's own tools, so a student can check Degrau's result:
//! MATLAB (`G = tf(num, den, 'InputDelay', θ)`) and python-control (`control.tf(num, den)`;
//! python-control's transfer functions carry no dead time, so a Padé approximant of it
//! stands in, said so in a comment).
//!
//! Every coefficient is written with the shortest digits that read back as the same double,
//! so the code describes exactly the system Degrau analysed. Code is not prose: it never
//! takes the language's decimal comma.

/// Order of the Padé approximant written for python-control's dead time.
pub const PYTHON_PADE_ORDER: usize = 5;

/// `x` as both MATLAB and Python read it back, exactly: the shortest round-trip digits,
/// in exponent form for very large or small magnitudes.
pub fn literal(x: f64) -> String {
    if x != 0.0 && (x.abs() >= 1e15 || x.abs() < 1e-5) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

fn row(v: &[f64], separator: &str) -> String {
    v.iter()
        .map(|&x| literal(x))
        .collect::<Vec<_>>()
        .join(separator)
}

/// The system a step of `amplitude` drives, as the code names it: `G`, or `A*G` after a
/// line setting A (MATLAB's `step(G)` is a unit step: its peak would be 1/A of Degrau's).
fn driven(amplitude: f64, comment: &str, end: &str) -> (String, &'static str) {
    if amplitude == 1.0 {
        (String::new(), "G")
    } else {
        (
            format!(
                "A = {}{end}  {comment} the step's amplitude\n",
                literal(amplitude)
            ),
            "A*G",
        )
    }
}

/// MATLAB (Control System Toolbox): `G = tf([…], […])`, with `'InputDelay', θ` when the
/// system has a dead time θ (s), and its response to a step of `amplitude`. Coefficients
/// in descending powers of s.
pub fn matlab(num: &[f64], den: &[f64], delay: f64, amplitude: f64) -> String {
    let delay = if delay > 0.0 {
        format!(", 'InputDelay', {}", literal(delay))
    } else {
        String::new()
    };
    let (set, system) = driven(amplitude, "%", ";");
    format!(
        "G = tf([{}], [{}]{delay});\n{set}step({system})\nstepinfo({system})",
        row(num, " "),
        row(den, " ")
    )
}

/// python-control: `G = control.tf([…], […])`; a dead time θ (s) becomes the Padé
/// approximant of order [`PYTHON_PADE_ORDER`], labelled as an approximation; its response
/// to a step of `amplitude`.
pub fn python_control(num: &[f64], den: &[f64], delay: f64, amplitude: f64) -> String {
    let mut code = format!(
        "import control\n\nG = control.tf([{}], [{}])\n",
        row(num, ", "),
        row(den, ", ")
    );
    if delay > 0.0 {
        code.push_str(&format!(
            "# dead time {} s: python-control's tf has none, so a Padé approximant of order \
             {PYTHON_PADE_ORDER} stands in (approximate)\nnum_d, den_d = control.pade({}, \
             {PYTHON_PADE_ORDER})\nG = G * control.tf(num_d, den_d)\n",
            literal(delay),
            literal(delay)
        ));
    }
    let (set, system) = driven(amplitude, "#", "");
    code.push_str(&format!(
        "{set}t, y = control.step_response({system})\nprint(control.step_info({system}))\n"
    ));
    code
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The numbers between the brackets after `start`, read back.
    fn numbers_after(code: &str, start: &str, separator: char) -> Vec<f64> {
        let from = code.find(start).unwrap() + start.len();
        let end = from + code[from..].find(']').unwrap();
        code[from..end]
            .split(separator)
            .map(|s| s.trim().parse().unwrap())
            .collect()
    }

    #[test]
    fn literals_read_back_exactly() {
        for x in [
            0.1,
            1.0 / 3.0,
            -2.5e-7,
            6.02214076e23,
            1e300,
            5e-324,
            123456.789,
            -0.0,
        ] {
            assert_eq!(literal(x).parse::<f64>().unwrap().to_bits(), x.to_bits());
        }
        assert_eq!(literal(0.5), "0.5");
        assert_eq!(literal(1e300), "1e300");
    }

    #[test]
    fn matlab_with_and_without_delay() {
        let num = [0.5];
        let den = [1.0, 7.0, 15.0, 25.0];
        let code = matlab(&num, &den, 0.0, 1.0);
        assert!(code.starts_with("G = tf([0.5], [1 7 15 25]);"), "{code}");
        assert!(!code.contains("InputDelay"));
        let code = matlab(&[2.0], &[10.0, 1.0], 1.0 / 3.0, 1.0);
        assert!(code.contains("'InputDelay', 0.3333333333333333"), "{code}");
        assert_eq!(numbers_after(&code, "tf([", ' '), vec![2.0]);
    }

    #[test]
    fn python_control_with_a_pade_delay() {
        let den = [1.0, 0.1 + 0.2, 1e-9];
        let code = python_control(&[1.0], &den, 2.5, 1.0);
        assert_eq!(numbers_after(&code, "], [", ','), den.to_vec());
        assert!(code.contains("control.pade(2.5, 5)"), "{code}");
        assert!(code.contains("approximate"));
        let plain = python_control(&[1.0], &[1.0, 1.0], 0.0, 1.0);
        assert!(!plain.contains("pade"));
        assert!(plain.contains("G = control.tf([1], [1, 1])"), "{plain}");
    }

    /// A step of amplitude A is A·G's unit step: the code says so, or MATLAB's peak is 1/A
    /// of Degrau's (issue 23, item 15).
    #[test]
    fn the_step_amplitude_is_in_the_code() {
        let code = matlab(&[0.5], &[1.0, 7.0, 15.0, 25.0], 0.0, 2.0);
        assert!(
            code.ends_with("A = 2;  % the step's amplitude\nstep(A*G)\nstepinfo(A*G)"),
            "{code}"
        );
        let code = python_control(&[1.0], &[1.0, 1.0], 0.0, -0.5);
        assert!(
            code.contains("A = -0.5  # the step's amplitude\n"),
            "{code}"
        );
        assert!(code.contains("control.step_response(A*G)") && code.contains("step_info(A*G)"));
    }
}
