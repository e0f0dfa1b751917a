!> The element seam: the one pass the explicit cycle calls per block (element_block_pass),
!> dispatched once per block (never per element) on the block's element type to its family
!> kernel, and the per-block set-up steps that depend on the family (mass share of the
!> element time-step bound). The family facts (nodes, faces, edges, volume, moments, lumped
!> mass, XDMF cell, partition weight), the pass result and the error codes are the table of
!> dx_element_types, re-exported here.
!> Families: hexahedron ELFORM 1 and 2 (dx_hex8: Flanagan & Belytschko 1981, IJNME
!> 17:679-706; Hughes 1980, IJNME 15:1413-1418), tetrahedron ELFORM 10 (dx_tet4: one-point
!> constant-strain tetrahedron; Zienkiewicz, Taylor & Zhu 2013, ch. 6), Belytschko-Lin-Tsay
!> shell ELFORM 2 of *SECTION_SHELL (dx_shell_bt: Belytschko, Lin & Tsay 1984, CMAME 42), 2D
!> quadrilaterals ELFORM 13, 14, 15 of *SECTION_SHELL (dx_quad2d: plane strain, area- and
!> volume-weighted axisymmetric; Hallquist, DYNA2D, UCID-18756; Flanagan & Belytschko 1981),
!> resultant beam ELFORM 2 of *SECTION_BEAM (dx_beam_bs: Belytschko, Schwer & Klein 1977,
!> IJNME 11), Hughes-Liu beam ELFORM 1 with cross-section integration (dx_beam_hl: Hughes & Liu
!> 1981, CMAME 26, 27), fully integrated shell ELFORM 16 (dx_shell_fi: Bathe & Dvorkin 1985,
!> IJNME 21).
module dx_element
   use dx_kinds, only: wp
   use dx_material, only: material_t
   use dx_element_types, only: elem_block_t, part_t, ES_PHIM, block_result_t, family_t, element_family, ELEM_ERR_NEGVOL, &
                               ELEM_ERR_MATERIAL, ETYPE_TET4, ETYPE_SHELL_BT, ETYPE_QUAD2D_PS, &
                               ETYPE_SHELL_FI, &
                               ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW, ETYPE_QUAD2D_PSS, ETYPE_BEAM_BS, &
                               ETYPE_BEAM_HL
   use dx_hex8, only: hex8_block, hex8_mass_share
   use dx_tet4, only: tet4_block
   use dx_shell_bt, only: shell_bt_block, shell_bt_rotary_inertia
   use dx_shell_fi, only: shell_fi_block
   use dx_quad2d, only: quad2d_block
   use dx_beam_bs, only: beam_bs_block, beam_bs_rotary_inertia
   use dx_beam_hl, only: beam_hl_block
   implicit none
   private
   public :: element_block_pass, element_mass_share, block_result_t, family_t, element_family
   public :: element_rotary_inertia
   public :: ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL

contains

   !> One explicit pass over a block: x = x(n), v = v(n-1/2), dt_old = dt(n-1/2). Updates
   !> stress/history to t(n), subtracts the internal force from f, returns the block's
   !> smallest element step, energy increments and first error. w = w(n-1/2), mom: the
   !> angular velocities and moments of a deck with shells (absent otherwise). time, dtfloor:
   !> a deck whose elements can erode (dx_erosion): the time t(n) and the element step below
   !> which an element erodes (*CONTROL_TIMESTEP ERODE = 1; 0: none).
   subroutine element_block_pass(blk, mat, part, x, v, dt_old, f, res, w, mom, time, dtfloor)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), intent(in), optional :: w(:, :)
      real(wp), intent(inout), optional :: mom(:, :)
      real(wp), intent(in), optional :: time, dtfloor
      select case (blk%etype)
      case (ETYPE_SHELL_BT)
         call shell_bt_block(blk, mat, part, part%shrf, part%lobatto, part%istupd, x, v, w, &
                             dt_old, f, mom, res)
      case (ETYPE_SHELL_FI)
         call shell_fi_block(blk, mat, part%shrf, part%lobatto, part%istupd, x, v, w, dt_old, &
                             f, mom, res)
      case (ETYPE_BEAM_BS)
         call beam_bs_block(blk, mat, x, v, w, dt_old, f, mom, res)
      case (ETYPE_BEAM_HL)
         call beam_hl_block(blk, mat, part, x, v, w, dt_old, f, mom, res)
      case (ETYPE_TET4)
         call tet4_block(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      case (ETYPE_QUAD2D_PS, ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW, ETYPE_QUAD2D_PSS)
         call quad2d_block(blk, mat, part, x, v, dt_old, f, res)
      case default
         call hex8_block(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      end select
   end subroutine element_block_pass

   !> After the lumped masses are known: the family's own-mass share of the element time-step
   !> bound (hexahedra of one-element-wide blocks; dx_hex8). mass, cnodes: the masses and
   !> constrained nodes as the block's connectivity indexes them.
   subroutine element_mass_share(blk, rho, mass, cnodes)
      type(elem_block_t), intent(inout) :: blk
      real(wp), intent(in) :: rho, mass(:)
      integer, intent(in) :: cnodes(:)
      select case (blk%etype)
      case (ETYPE_TET4, ETYPE_SHELL_BT, ETYPE_SHELL_FI, ETYPE_QUAD2D_PS, ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW, &
            ETYPE_QUAD2D_PSS, ETYPE_BEAM_BS, ETYPE_BEAM_HL)
         call blk%es_drop(ES_PHIM)
      case default
         call hex8_mass_share(blk, rho, mass, cnodes)
      end select
   end subroutine element_mass_share

   !> Add the lumped rotary inertia of a block whose family has rotations to rinert (rho:
   !> the part's density; rotascl: *CONTROL_SHELL ROTASCL).
   subroutine element_rotary_inertia(blk, rho, rotascl, rinert)
      type(elem_block_t), intent(in) :: blk
      real(wp), intent(in) :: rho, rotascl
      real(wp), intent(inout) :: rinert(:)
      select case (blk%etype)
      case (ETYPE_SHELL_BT, ETYPE_SHELL_FI)     ! the same lumping (dx_shell_fi)
         call shell_bt_rotary_inertia(blk, rho, rotascl, rinert)
      case (ETYPE_BEAM_BS, ETYPE_BEAM_HL)   ! (ROTASCL is *CONTROL_SHELL's: shells only)
         call beam_bs_rotary_inertia(blk, rho, rinert)
      end select
   end subroutine element_rotary_inertia
end module dx_element
