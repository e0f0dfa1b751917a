!> Kernels shared by the solid families (dx_hex8, dx_tet4), per element or per block:
!> - hex8_mass_share: the set-up of dx_hex8's own-mass element bound (phim, ES_PHIM);
!> - cube_roots: V**(1/3) from exactly rounded operations only (the same bits in every SIMD
!>   lane): the cbrt start of FreeBSD's s_cbrt.c, Halley's iteration (Traub 1964, Iterative
!>   Methods for the Solution of Equations, sec. 8.4) and one Newton step;
!> (centred_work, the other kernel both use, stays in dx_hex8, public: moved out of that
!> module it is no longer inlined into hex8_sri, and the FMA contraction of ELFORM 2's
!> pending work changed the last digit of its internal energy, e.g. glstat of
!> patch_rigid_rotation_elform2, 9.8628816051E-006 -> ...053E-006.)
module dx_solid_kernels
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp
   use dx_element_types, only: elem_block_t, ES_PHIM
   implicit none
   private
   public :: cube_roots, hex8_mass_share

contains

   !> l(1:n) = x(1:n)**(1/3) from exactly rounded operations only, so a vectorized loop
   !> gives every element the same bits in every lane and in the scalar remainder. (pow not:
   !> gfortran pre-includes glibc's math-vector-fortran.h, and the vector body then calls
   !> libmvec's SIMD pow, the remainder scalar libm pow; an element's result depended on its
   !> position in its block, and an MPI rank's piece of a block changes positions.)
   !> Start: the bit pattern of x divided by 3 plus the exponent bias term (the classic
   !> cbrt start, as in FreeBSD's s_cbrt.c; within 3.3 % here), done through a double so the
   !> loop vectorizes; then two steps of Halley's iteration l <- l (l^3 + 2x)/(2 l^3 + x)
   !> (cubic convergence; Traub 1964, Iterative Methods for the Solution of Equations,
   !> sec. 8.4) and one Newton step: within 3 ulp of the correctly rounded cube root on
   !> 1e-90..1e90 (2e5 random samples; pow(x, 1/3) is itself off by up to 16 ulp at
   !> 1e+-40, 1/3 not being a double). Valid for volumes in 1e-90..1e90 (any consistent
   !> units); x <= 0 gives 0. One loop without calls, so it vectorizes; integer/real
   !> conversions, +, *, / are exact or correctly rounded in every lane.
   subroutine cube_roots(n, x, l)
      integer, intent(in) :: n
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: l(:)
      integer(int64), parameter :: CBRT_BIAS = 3071306043645493248_int64   ! 715094163*2**32
      real(wp) :: y, r, r3
      integer :: i
      do i = 1, n
         y = max(x(i), 1.0e-90_wp)
         r = transfer(int(real(transfer(y, 0_int64), wp)/3.0_wp, int64) + CBRT_BIAS, 1.0_wp)
         r3 = r*r*r
         r = r*(r3 + 2.0_wp*y)/(2.0_wp*r3 + y)
         r3 = r*r*r
         r = r*(r3 + 2.0_wp*y)/(2.0_wp*r3 + y)
         r = r - (r*r*r - y)/(3.0_wp*r*r)
         l(i) = merge(r, 0.0_wp, x(i) > 0.0_wp)
      end do
   end subroutine cube_roots

   !> After the lumped masses are known: the element's own share of its nodes' mass,
   !> phim = (1/8) sum_I (rho V0/8)/m_I (1 for a free element, 1/2 inside a one-element-wide
   !> bar, 1/8 inside a mesh); a node with a constrained translation (SPC, prescribed motion:
   !> the list cnodes) counts as restrained (share 0). Allocated only for a block that has an
   !> element with phim >= 1/2, the only case stable_time_step uses it.
   subroutine hex8_mass_share(blk, rho, mass, cnodes)
      type(elem_block_t), intent(inout) :: blk
      real(wp), intent(in) :: rho, mass(:)
      integer, intent(in) :: cnodes(:)
      real(wp) :: phi(blk%nel)
      logical :: free(size(mass))
      integer :: i, k, nd
      free = .true.
      free(cnodes) = .false.
      do i = 1, blk%nel
         phi(i) = 0.0_wp
         do k = 1, 8
            nd = blk%conn(k, i)
            if (free(nd) .and. mass(nd) > 0.0_wp) &
               phi(i) = phi(i) + rho*blk%vol0(i)/(64.0_wp*mass(nd))
         end do
      end do
      call blk%es_drop(ES_PHIM)
      if (any(phi >= 0.5_wp)) then
         call blk%es_add(ES_PHIM, 1)
         blk%es(:, blk%esc(ES_PHIM)) = phi
      end if
   end subroutine hex8_mass_share

end module dx_solid_kernels
