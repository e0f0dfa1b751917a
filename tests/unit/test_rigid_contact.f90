!> Unit test of the contact frequency bound on rigid bodies (dx_rigid_contact) against hand
!> values of sum_i krow_i (1/M + r_i^2/I1): a free body (M = 2, I1 = 0.5; krow 10 at r = 1,
!> krow 4 at r = 2: 10 (0.5 + 2) + 4 (0.5 + 8) = 59), a fully fixed body (CON1 = CON2 = 7:
!> 0 whatever its springs), a body with fixed translations (M = 1, I1 = 1, krow 2 at r = 3:
!> 2 x 9 = 18), a deformable node (ignored here); the bound is the largest body, 59, to 1e-14.
!> Effective masses 1/(1/M + r^2/I1): 0.4 and 1/8.5 on the free body, huge on the fixed one,
!> 1/9 with fixed translations; deformable entries untouched.
program test_rigid_contact
   use dx_kinds, only: wp
   use dx_rigid_types, only: rigid_system_t
   use dx_rigid_contact, only: rigid_contact_w2, rigid_effective_mass
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(rigid_system_t) :: rs
   real(wp) :: x(3, 5), krow(5), meff(5)
   integer :: nodes(5)

   allocate(rs%bodies(3))
   rs%node_body = [1, 1, 2, 3, 0]
   rs%bodies(1)%mass = 2.0_wp
   rs%bodies(1)%ip = [0.5_wp, 1.0_wp, 2.0_wp]
   rs%bodies(1)%xc = [1.0_wp, 1.0_wp, 1.0_wp]
   rs%bodies(2)%mass = 1.0e-3_wp
   rs%bodies(2)%ip = [1.0e-6_wp, 1.0e-6_wp, 1.0e-6_wp]
   rs%bodies(2)%fix_t = .true.
   rs%bodies(2)%fix_r = .true.
   rs%bodies(3)%mass = 1.0_wp
   rs%bodies(3)%ip = [1.0_wp, 1.0_wp, 1.0_wp]
   rs%bodies(3)%fix_t = .true.
   x(:, 1) = [2.0_wp, 1.0_wp, 1.0_wp]      ! r = 1 from body 1's centre
   x(:, 2) = [1.0_wp, 3.0_wp, 1.0_wp]      ! r = 2
   x(:, 3) = [5.0_wp, 5.0_wp, 5.0_wp]
   x(:, 4) = [0.0_wp, 0.0_wp, 3.0_wp]      ! r = 3 from body 3's centre (origin)
   x(:, 5) = [9.0_wp, 9.0_wp, 9.0_wp]
   krow = [10.0_wp, 4.0_wp, 1.0e6_wp, 2.0_wp, 100.0_wp]
   nodes = [1, 2, 3, 4, 5]

   call check_close(rigid_contact_w2(rs, nodes, krow, x), 59.0_wp, 0.0_wp, 1.0e-14_wp, &
                    'w2 bound: largest body (free body, 59)')
   call check_close(rigid_contact_w2(rs, [3], krow, x), 0.0_wp, 0.0_wp, 0.0_wp, &
                    'w2 bound: fully fixed body adds nothing')
   call check_close(rigid_contact_w2(rs, [4, 5], krow, x), 18.0_wp, 0.0_wp, 1.0e-14_wp, &
                    'w2 bound: fixed translations keep r^2/I1 (18); deformable node ignored')
   meff = -1.0_wp
   call rigid_effective_mass(rs, nodes, x, meff)
   call check_close(meff(1), 0.4_wp, 0.0_wp, 1.0e-14_wp, 'effective mass, r = 1')
   call check_close(meff(2), 1.0_wp/8.5_wp, 0.0_wp, 1.0e-14_wp, 'effective mass, r = 2')
   call check(meff(3) == huge(1.0_wp), 'effective mass of a fixed body is huge')
   call check_close(meff(4), 1.0_wp/9.0_wp, 0.0_wp, 1.0e-14_wp, 'effective mass, fixed translations')
   call check(meff(5) == -1.0_wp, 'deformable node left alone')
   call assert_summary()
end program test_rigid_contact
