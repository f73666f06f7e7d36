//! The Avalon-MM agent port shape shared by the register file and every top that exposes it,
//! so that one bus model (in `skylux-sim`) can drive any of them.

use rust_hdl::prelude::*;
use skylux_regmap::AVALON_WORD_ADDRESS_BITS as A;

/// A design with a 32-bit Avalon-MM agent port named `avs_*` and a system clock `clock`.
pub trait AvalonAgent: Block {
    fn clock(&mut self) -> &mut Signal<In, Clock>;
    fn avs_address(&mut self) -> &mut Signal<In, Bits<A>>;
    fn avs_read(&mut self) -> &mut Signal<In, Bit>;
    fn avs_write(&mut self) -> &mut Signal<In, Bit>;
    fn avs_writedata(&mut self) -> &mut Signal<In, Bits<32>>;
    fn avs_byteenable(&mut self) -> &mut Signal<In, Bits<4>>;
    fn avs_readdata(&self) -> Bits<32>;
}

/// Implements [`AvalonAgent`] for a block whose ports carry the standard names.
#[macro_export]
macro_rules! impl_avalon_agent {
    ($t:ty) => {
        impl $crate::avalon::AvalonAgent for $t {
            fn clock(&mut self) -> &mut Signal<In, Clock> {
                &mut self.clock
            }
            fn avs_address(
                &mut self,
            ) -> &mut Signal<In, Bits<{ skylux_regmap::AVALON_WORD_ADDRESS_BITS }>> {
                &mut self.avs_address
            }
            fn avs_read(&mut self) -> &mut Signal<In, Bit> {
                &mut self.avs_read
            }
            fn avs_write(&mut self) -> &mut Signal<In, Bit> {
                &mut self.avs_write
            }
            fn avs_writedata(&mut self) -> &mut Signal<In, Bits<32>> {
                &mut self.avs_writedata
            }
            fn avs_byteenable(&mut self) -> &mut Signal<In, Bits<4>> {
                &mut self.avs_byteenable
            }
            fn avs_readdata(&self) -> Bits<32> {
                self.avs_readdata.val()
            }
        }
    };
}

impl_avalon_agent!(crate::RegisterFile);
