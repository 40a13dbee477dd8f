//! Selection and feedback (section 5.2, 5.3).

use super::Context;
use crate::api::convert::StateExtQuery;

impl Context {
    pub(crate) fn select_state_value(&self, q: StateExtQuery) -> super::get::StateValue {
        let _ = q;
        super::get::StateValue::Ints(vec![0])
    }
}
